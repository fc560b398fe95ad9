#include "model/replace/pattern_folder.hpp"

#include <algorithm>

#include "model/core/error.hpp"
#include "model/map_io/map_json.hpp"

namespace gmr::replace {

Pattern load_pattern(const std::filesystem::path& file) {
  const EmbeddedMap f = io::read_map_json_file(file);
  return make_pattern(file.string(), flagged_map(f, file.string()));
}

std::vector<Pattern> load_patterns(const std::filesystem::path& folder) {
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec))
    throw Error(ErrorCode::Io, "not a folder of patterns", folder.string());
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(folder))
    if (e.is_regular_file() && e.path().extension() == ".json") files.push_back(e.path());
  if (files.empty())
    throw Error(ErrorCode::Io, "no pattern file (*.json) in the folder", folder.string());
  std::sort(files.begin(), files.end());
  std::vector<Pattern> out;
  for (const auto& file : files) {
    out.push_back(load_pattern(file));
    out.back().name = file.stem().string();
  }
  return out;
}

}  // namespace gmr::replace
