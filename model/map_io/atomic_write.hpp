// Atomic file output (writers write atomically).
//
// The content goes to a fresh temporary file in the destination's directory (so that the final
// rename stays within one file system), is flushed to disk, then renamed over the destination.
// Readers therefore see either the old file or the complete new one. On any failure the temporary
// file is removed, the destination is left untouched, and Error(Io) names the path.
// A symbolic link is written through (its target is replaced, the link stays); a destination that
// exists and is not a regular file (FIFO, character device) is opened and written in place.
#pragma once
#include <filesystem>
#include <string_view>

namespace gmr::io {

void write_file_atomic(const std::filesystem::path& path, std::string_view content);

// Installs SIGINT/SIGTERM handlers that remove the temporary files of writes in progress, then
// terminate by the same signal (for programs: the library never installs handlers by itself).
void remove_temporaries_on_signal();

}  // namespace gmr::io
