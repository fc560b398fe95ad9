// A test's scratch folder under the system's temporary directory, named after the test and the
// process, so that two checkouts (or two test commands) running the same test at once do not
// share it.
#pragma once
#include <unistd.h>

#include <filesystem>
#include <string>

namespace gmr::testing {

inline std::filesystem::path scratch_path(const std::string& name) {
  return std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
}

}  // namespace gmr::testing
