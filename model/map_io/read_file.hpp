// Whole-file input for the readers (JSON, OFF, ...): the text of a file, or Error(Io) naming it.
// The path "-" reads standard input.
#pragma once
#include <filesystem>
#include <string>

namespace gmr::io {

std::string read_text_file(const std::filesystem::path& path);

}  // namespace gmr::io
