#include "tools/cli/orbit_list.hpp"

#include <regex>

#include "model/core/error.hpp"

namespace gmr::cli {

std::vector<OrbitType> parse_orbit_list(const std::string& text) {
  std::vector<OrbitType> out;
  const std::regex item(R"(\s*(<[^>]*>)\s*(,|$))");
  auto it = text.cbegin();
  std::smatch m;
  while (it != text.cend()) {
    if (!std::regex_search(it, text.cend(), m, item, std::regex_constants::match_continuous))
      throw Error(ErrorCode::Usage,
                  "expected a list of orbit types such as \"<0,1>,<1,2>\", found \"" + text + "\"",
                  "--orbits");
    try {
      out.push_back(OrbitType::parse(m[1].str()));
    } catch (const Error& e) {
      throw Error(e.code(), e.message() + " (" + e.location() + ")", "--orbits");
    }
    it = m[0].second;
  }
  return out;
}

}  // namespace gmr::cli
