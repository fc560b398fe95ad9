#include "model/map_io/read_file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

#include "model/core/error.hpp"
#include "model/map_io/read_limits.hpp"

namespace gmr::io {

std::string read_text_file(const std::filesystem::path& path) {
  const uint64_t limit = read_limits().max_input_bytes;
  auto too_large = [&](const std::string& size) {
    return Error(ErrorCode::Range,
                 "input of " + size + " bytes, above the limit of " + std::to_string(limit) +
                     " bytes (set GMR_MAX_INPUT_BYTES to raise it)",
                 path.string());
  };
  if (path == "-") {
    std::string text;
    char buffer[1 << 16];
    while (std::cin.read(buffer, sizeof buffer) || std::cin.gcount() > 0) {
      text.append(buffer, static_cast<size_t>(std::cin.gcount()));
      if (text.size() > limit) throw too_large("more than " + std::to_string(limit));
    }
    return text;
  }
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw Error(ErrorCode::Io, "is a directory, not a file", path.string());
  if (std::filesystem::is_regular_file(path, ec)) {
    const uint64_t size = std::filesystem::file_size(path, ec);
    if (!ec && size > limit) throw too_large(std::to_string(size));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw Error(ErrorCode::Io, std::string("cannot open: ") + std::strerror(errno), path.string());
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw Error(ErrorCode::Io, "read failed", path.string());
  return text;
}

}  // namespace gmr::io
