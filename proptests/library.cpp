#include "proptests/library.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "checker/scheme_checker.hpp"
#include "model/core/error.hpp"
#include "model/rule_io/jme_import.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "model/testing/source_tree.hpp"

namespace gmr::prop {
using namespace gmr::scheme;
using namespace gmr::io;
using namespace gmr::checker;

const std::vector<LibraryScheme>& scheme_library() {
  static const std::vector<LibraryScheme> lib = [] {
    std::vector<LibraryScheme> out;
    const std::string root = gmr::testing::source_path(".");
    std::vector<std::pair<RuleScheme, bool>> all;
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(root + "/tools/data/rules"))
      files.push_back(e.path());
    std::sort(files.begin(), files.end());  // directory order is not portable
    for (const auto& f : files) all.emplace_back(read_scheme_file(f), true);
    for (auto& s : read_jme_file(root + "/tools/data/jerboa/JerboaTrackingOrbit.jme").rules)
      all.emplace_back(s, false);
    for (auto& [s, standard] : all) {
      std::shared_ptr<const SchemeEngine> e;
      try {
        e = std::make_shared<const SchemeEngine>(s);
      } catch (const Error&) {
        continue;
      }
      if (!e->not_combinatorial().empty()) continue;
      out.push_back(
          {s, check_scheme(s, {.embeddings = false}).ok(), standard, e});  // topological properties
    }
    return out;
  }();
  return lib;
}

std::vector<size_t> library_of_dim(int n, bool accepted_only) {
  std::vector<size_t> out;
  const auto& lib = scheme_library();
  for (size_t k = 0; k < lib.size(); ++k)
    if (lib[k].scheme.dimension == n && (!accepted_only || lib[k].accepted)) out.push_back(k);
  return out;
}

}  // namespace gmr::prop
