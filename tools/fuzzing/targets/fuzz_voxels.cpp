// gmr.voxels JSON: read, and build the polycube of small sets (what `gmr info` does with one).
#include "model/core/validity.hpp"
#include "model/map_io/voxels.hpp"
#include "tools/fuzzing/fuzz_target.hpp"

void gmr::fuzzing::fuzz_one(std::string_view text) {
  const std::vector<Voxel> voxels = io::read_voxels_json(text, "fuzz.json");
  if (voxels.size() > 64) return;
  if (!is_valid(make_polycube(voxels))) __builtin_trap();  // a polycube is always a valid 3-G-map
}
