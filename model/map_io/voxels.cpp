#include "model/map_io/voxels.hpp"

#include <map>

#include "model/map_io/json_reader.hpp"
#include "model/map_io/read_file.hpp"

namespace gmr::io {

std::vector<Voxel> read_voxels_json(std::string_view text, const std::string& source) {
  const nlohmann::json doc = parse_json(text, source);
  return voxels_from_json(JsonAt(doc, source));
}

std::vector<Voxel> voxels_from_json(const JsonAt& at) {
  at.check_header("gmr.voxels", 1);
  at.allow_only({"format", "version", "voxels"});
  const JsonAt list = at["voxels"];
  const size_t count = list.array_size();
  std::vector<Voxel> voxels;
  voxels.reserve(count);
  std::map<Voxel, size_t> seen;
  constexpr int64_t kLimit = int64_t(1) << 20;
  for (size_t k = 0; k < count; ++k) {
    const JsonAt v = list[k];
    if (v.array_size() != 3)
      v.fail("expected a voxel [x, y, z], found " + std::to_string(v.array_size()) + " values");
    Voxel vx{};
    for (size_t a = 0; a < 3; ++a) vx[a] = static_cast<int>(v[a].as_int(-kLimit, kLimit));
    if (auto [it, fresh] = seen.emplace(vx, k); !fresh)
      v.fail("duplicate voxel (same as " + list.child_path(it->second) + ")");
    voxels.push_back(vx);
  }
  return voxels;
}

std::vector<Voxel> read_voxels_json_file(const std::filesystem::path& path) {
  return read_voxels_json(read_text_file(path), path.string());
}

}  // namespace gmr::io
