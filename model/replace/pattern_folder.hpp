// A pattern set on disk: every *.json file of a folder is a gmr.gmap file holding one pattern
// (flags as the embedding "flag"), named by its file stem; files are read in name order.
#pragma once
#include <filesystem>
#include <vector>

#include "model/replace/pattern.hpp"

namespace gmr::replace {

// Throws Error(Io) for a missing folder or one without pattern files, and the located error of
// the first file that is not a valid pattern (Error(Parse)/Error(Schema) naming the file).
std::vector<Pattern> load_patterns(const std::filesystem::path& folder);
Pattern load_pattern(const std::filesystem::path& file);

}  // namespace gmr::replace
