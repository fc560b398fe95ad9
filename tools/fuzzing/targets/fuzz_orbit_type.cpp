// Orbit-type notation ("<0,1,2>", "<_,1>", "<>"): parse, print, parse back.
#include "model/core/orbit_type.hpp"
#include "tools/fuzzing/fuzz_target.hpp"

void gmr::fuzzing::fuzz_one(std::string_view text) {
  const OrbitType o = OrbitType::parse(text);
  if (!(OrbitType::parse(o.str()) == o))
    __builtin_trap();  // the printer's output parses back alike
}
