// Resource limits of the readers, checked before anything is allocated for the input: the size
// of an input file (the JSON document of a file takes about 16 bytes per value in memory) and the
// number of darts a file may declare or build. Defaults below; the environment variables
// GMR_MAX_INPUT_BYTES and GMR_MAX_DARTS (decimal integers) raise or lower them.
#pragma once
#include <cstdint>
#include <string>

namespace gmr::io {

inline constexpr uint64_t kDefaultMaxInputBytes = uint64_t{512} << 20;  // 512 MiB
inline constexpr uint64_t kDefaultMaxDarts = uint64_t{1} << 27;         // 134,217,728 darts

struct ReadLimits {
  uint64_t max_input_bytes = kDefaultMaxInputBytes;
  uint64_t max_darts = kDefaultMaxDarts;
};

// The limits in force (read once from the environment; an unreadable value is Error(Usage)
// naming the variable).
const ReadLimits& read_limits();

// Error(Range) located at `where` when `darts` exceeds the dart limit.
void check_dart_limit(uint64_t darts, const std::string& where);

}  // namespace gmr::io
