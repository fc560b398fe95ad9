#include "model/map_io/line_tokens.hpp"

namespace gmr::io {

std::vector<std::string_view> line_tokens(std::string_view line) {
  if (const size_t hash = line.find('#'); hash != std::string_view::npos)
    line = line.substr(0, hash);
  auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; };
  std::vector<std::string_view> tokens;
  size_t p = 0;
  while (p < line.size()) {
    while (p < line.size() && blank(line[p])) ++p;
    const size_t q = p;
    while (p < line.size() && !blank(line[p])) ++p;
    if (p > q) tokens.push_back(line.substr(q, p - q));
  }
  return tokens;
}

}  // namespace gmr::io
