// OFF meshes: read into a 2-G-map with positions (non-manifold input is a named error).
#include "model/core/validity.hpp"
#include "model/map_io/off.hpp"
#include "tools/fuzzing/fuzz_target.hpp"

void gmr::fuzzing::fuzz_one(std::string_view text) {
  const EmbeddedMap m = io::read_off(text, "fuzz.off");
  if (!is_valid(m.map)) __builtin_trap();  // the reader only builds valid maps
}
