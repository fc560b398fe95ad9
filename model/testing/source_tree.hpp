// Where tests find the repository's data files: the source tree named by GMR_SOURCE_DIR, which
// CTest sets for every test (CMakeLists.txt, GMR_TEST_ENV), or the current directory when unset
// (a test executable run by hand from the checkout's root). The build's own artifacts (GMR_BIN, the
// gmr binary; GMR_PLUGIN_DIR, the condition plug-ins) come through the same environment.
#pragma once
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace gmr::testing {

// The path of `relative` (e.g. "tools/data/cube.off") in the source tree.
inline std::string source_path(const std::string& relative) {
  const char* root = std::getenv("GMR_SOURCE_DIR");
  return std::string(root ? root : ".") + "/" + relative;
}

// The value of the environment variable `variable` naming a build artifact; throws when the test
// is not run through CTest (which sets it).
inline std::string build_artifact(const char* variable) {
  const char* value = std::getenv(variable);
  if (!value)
    throw std::runtime_error(std::string(variable) + " is not set: run the test through ctest");
  return value;
}

}  // namespace gmr::testing
