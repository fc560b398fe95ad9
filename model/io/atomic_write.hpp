// Atomic file output (writers write atomically).
//
// The content goes to a fresh temporary file in the destination's directory (so that the final
// rename stays within one file system), is flushed to disk, then renamed over the destination.
// Readers therefore see either the old file or the complete new one. On any failure the temporary
// file is removed, the destination is left untouched, and Error(Io) names the path.
#pragma once
#include <filesystem>
#include <string_view>

namespace gmr::io {

void write_file_atomic(const std::filesystem::path& path, std::string_view content);

}  // namespace gmr::io
