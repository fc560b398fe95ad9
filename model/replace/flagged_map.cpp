#include "model/replace/flagged_map.hpp"

#include "model/core/error.hpp"
#include "model/core/huge_pages.hpp"
#include "model/core/orbit.hpp"
#include "model/core/position.hpp"

namespace gmr::replace {

void FlaggedMap::grow_flags(size_t darts) {
  grow_in_huge_pages(flag, darts);
  if (positioned()) grow_in_huge_pages(position, darts);
}

void FlaggedMap::reserve(size_t darts) {
  map.reserve(darts);
  reserve_in_huge_pages(flag, darts);
  if (positioned()) reserve_in_huge_pages(position, darts);
}

size_t FlaggedMap::flagged() const {
  size_t n = 0;
  map.for_each_dart([&](Dart d) { n += d < flag.size() && flag[d] != 0; });
  return n;
}

FlaggedMap flagged_map(const GMapFile& f, const std::string& where) {
  FlaggedMap m{f.map, {}, {}};
  if (const JsonEmbedding* pe = f.find(kPositionName)) {
    const PositionEmbedding pos = position_from_json(f.map, *pe);
    m.position.assign(f.map.capacity(), Vec3{0, 0, 0});
    f.map.for_each_dart([&](Dart d) {
      if (pos.has(d)) m.position[d] = pos.get(d);
    });
  }
  m.resize_flags();
  const JsonEmbedding* e = f.find(kFlagEmbedding);
  if (!e) return m;
  if (e->orbit_type().size() != 0)
    throw Error(ErrorCode::Schema, "the embedding \"flag\" must be on the orbit type <> (one value per dart), not " +
                                       e->orbit_type().str(), where);
  m.map.for_each_dart([&](Dart d) {
    if (!e->has(d)) return;
    const nlohmann::json& v = e->get(d);
    if (v.is_boolean()) m.flag[d] = v.get<bool>() ? 1 : 0;
    else if (v.is_number_unsigned()) m.flag[d] = v.get<uint32_t>();
    else if (v.is_number_integer() && v.get<long long>() >= 0) m.flag[d] = static_cast<uint32_t>(v.get<long long>());
    else
      throw Error(ErrorCode::Schema, "a flag is a boolean or a non-negative integer, not " + v.dump(),
                  where + (where.empty() ? "" : ": ") + "dart " + std::to_string(d));
  });
  return m;
}

GMapFile to_gmap_file(const FlaggedMap& m) {
  GMapFile f;
  f.map = m.map;
  JsonEmbedding e(kFlagEmbedding, OrbitType{});
  m.map.for_each_dart([&](Dart d) {
    const uint32_t v = d < m.flag.size() ? m.flag[d] : 0;
    e.set_dart(m.map, d, v <= 1 ? nlohmann::json(v == 1) : nlohmann::json(v));
  });
  f.embeddings.push_back(std::move(e));
  if (m.positioned()) {
    PositionEmbedding pos(kPositionName, vertex_orbit_type(m.map));
    for (Dart v : orbit_representatives(m.map, vertex_orbit_type(m.map))) pos.set(m.map, v, m.position[v]);
    f.embeddings.push_back(position_to_json(m.map, pos));
  }
  return f;
}

}  // namespace gmr::replace
