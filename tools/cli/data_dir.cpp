// The data folder of the gmr command line (tools/CMakeLists.txt gives GMR_DATA_DIR to this file
// only).
#include <filesystem>
#include <string>

#include "tools/cli/cli.hpp"

namespace gmr::cli {

std::string default_data_dir() {
  // From the checkout's root (as the README runs gmr), else the source tree gmr was built from.
  std::error_code ec;
  if (std::filesystem::is_directory("tools/data/rules", ec)) return "tools/data";
  return GMR_DATA_DIR;
}

}  // namespace gmr::cli
