#include "model/map_io/read_limits.hpp"

#include <cstdlib>
#include <string>

#include "model/core/error.hpp"

namespace gmr::io {

namespace {

uint64_t from_environment(const char* name, uint64_t fallback) {
  const char* text = std::getenv(name);
  if (!text || !*text) return fallback;
  char* end = nullptr;
  const unsigned long long v = std::strtoull(text, &end, 10);
  if (*end != '\0' || text[0] == '-')
    throw Error(ErrorCode::Usage,
                std::string("expected a non-negative integer, found \"") + text + "\"", name);
  return v;
}

}  // namespace

const ReadLimits& read_limits() {
  static const ReadLimits limits{from_environment("GMR_MAX_INPUT_BYTES", kDefaultMaxInputBytes),
                                 from_environment("GMR_MAX_DARTS", kDefaultMaxDarts)};
  return limits;
}

void check_dart_limit(uint64_t darts, const std::string& where) {
  const uint64_t limit = read_limits().max_darts;
  if (darts > limit)
    throw Error(ErrorCode::Range,
                "the input needs " + std::to_string(darts) + " darts, above the limit of " +
                    std::to_string(limit) + " (set GMR_MAX_DARTS to raise it)",
                where);
}

}  // namespace gmr::io
