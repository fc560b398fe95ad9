// Where tests find the repository's data files: the source tree named by GMR_SOURCE_DIR, which
// CTest sets for every test (CMakeLists.txt, GMR_TEST_ENV), or the current directory when unset
// (a test executable run by hand from the checkout's root).
#pragma once
#include <cstdlib>
#include <string>

namespace gmr::testing {

// The path of `relative` (e.g. "tools/data/cube.off") in the source tree.
inline std::string source_path(const std::string& relative) {
  const char* root = std::getenv("GMR_SOURCE_DIR");
  return std::string(root ? root : ".") + "/" + relative;
}

}  // namespace gmr::testing
