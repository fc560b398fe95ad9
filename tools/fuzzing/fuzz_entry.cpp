// The libFuzzer entry point of every target (fuzz_target.hpp): bad input reported as a gmr::Error
// is the expected outcome; any other exception escapes and is a finding.
#include <cstddef>
#include <cstdint>

#include "model/core/error.hpp"
#include "tools/fuzzing/fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    gmr::fuzzing::fuzz_one(std::string_view(reinterpret_cast<const char*>(data), size));
  } catch (const gmr::Error&) {
    // bad input, reported with a location
  }
  return 0;
}
