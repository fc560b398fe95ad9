// How often a test finds a piece of text in an output (DOT, JSON, messages).
#pragma once
#include <string>

namespace gmr::testing {

// The number of occurrences of `what` in `text`, overlapping ones included.
inline size_t count_occurrences(const std::string& text, const std::string& what) {
  size_t k = 0;
  for (size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++k;
  return k;
}

}  // namespace gmr::testing
