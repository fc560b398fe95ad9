#include "tools/cli/match_syntax.hpp"

#include <cctype>
#include <sstream>

#include "model/core/error.hpp"

namespace gmr::cli {
using namespace gmr::graph;
using namespace gmr::rewrite;

std::vector<std::pair<Node, Dart>> parse_match_pairs(const Rule& r, const Map& g,
                                                     const std::string& text) {
  std::vector<std::pair<Node, Dart>> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    const auto eq = item.find('=');
    if (eq == std::string::npos)
      throw Error(ErrorCode::Usage, "expected NODE=DART, found \"" + item + "\"", "--match");
    const std::string name = item.substr(0, eq), dart = item.substr(eq + 1);
    const auto v = r.left().find(name);
    if (!v)
      throw Error(ErrorCode::Usage, "no node \"" + name + "\" in the left-hand side", "--match");
    for (const auto& [node, dart_given] : out)
      if (node == *v)
        throw Error(ErrorCode::Usage, "node \"" + name + "\" is given twice", "--match");
    size_t used = 0;
    unsigned long d = 0;
    try {
      d = std::stoul(dart, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    const bool digits_only = !dart.empty() && std::isdigit(static_cast<unsigned char>(dart[0]));
    if (!digits_only || used != dart.size() || d >= g.capacity() || !g.alive(static_cast<Dart>(d)))
      throw Error(ErrorCode::Usage, "\"" + dart + "\" is not a dart of the map", "--match " + item);
    out.emplace_back(*v, static_cast<Dart>(d));
  }
  return out;
}

}  // namespace gmr::cli
