// gmr.gmap JSON: read, validate, write and read back (what `gmr validate` and `gmr convert` do).
#include "model/core/validity.hpp"
#include "model/io/gmap_json.hpp"
#include "tools/fuzzing/fuzz_target.hpp"

void gmr::fuzzing::fuzz_one(std::string_view text) {
  const GMapFile f = io::read_gmap_json(text, "fuzz.json");
  (void)check_validity(f.map, 10);
  if (f.map.size() > 4096) return;
  const GMapFile back = io::read_gmap_json(io::write_gmap_json(f), "written.json");
  if (back.map.size() != f.map.size()) __builtin_trap();  // the writer's output must read back alike
}
