// gmr.gmap JSON: read, validate, write and read back (what `gmr validate` and `gmr convert` do).
#include "model/core/validity.hpp"
#include "model/map_io/map_json.hpp"
#include "tools/fuzzing/fuzz_target.hpp"

void gmr::fuzzing::fuzz_one(std::string_view text) {
  const EmbeddedMap f = io::read_map_json(text, "fuzz.json");
  (void)check_validity(f.map, 10);
  if (f.map.size() > 4096) return;
  const EmbeddedMap back = io::read_map_json(io::write_map_json(f), "written.json");
  if (back.map.size() != f.map.size())
    __builtin_trap();  // the writer's output must read back alike
}
