// The text form shared by every property-test case (MapCase, RuleCase, SchemeCase) and by the
// corpus files: "<family> <n> <size> <seed>".
#pragma once
#include <cstdint>
#include <optional>
#include <sstream>
#include <string>

namespace gmr::prop {

struct CaseLine {
  std::string family;
  int n = 0;
  size_t size = 0;
  uint64_t seed = 0;

  std::string str() const {
    return family + " " + std::to_string(n) + " " + std::to_string(size) + " " +
           std::to_string(seed);
  }
  // nullopt when a field is missing or malformed, or size == 0.
  static std::optional<CaseLine> parse(const std::string& line) {
    std::istringstream ss(line);
    CaseLine c;
    if (!(ss >> c.family >> c.n >> c.size >> c.seed) || c.size == 0) return std::nullopt;
    return c;
  }
};

}  // namespace gmr::prop
