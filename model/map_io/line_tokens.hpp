// The line-oriented text formats (OFF, OBJ): one statement per line, '#' starting a comment,
// tokens separated by blanks.
#pragma once
#include <string_view>
#include <vector>

namespace gmr::io {

// The blank-separated tokens of `line` before any '#'.
std::vector<std::string_view> line_tokens(std::string_view line);

}  // namespace gmr::io
