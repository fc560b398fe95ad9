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

FlaggedMap flagged_map(const EmbeddedMap& f, const std::string& where) {
  FlaggedMap m{f.map, {}, {}};
  if (f.find(kPositionName)) {
    const PositionEmbedding& pos = f.position();
    m.position.assign(f.map.capacity(), Vec3{0, 0, 0});
    f.map.for_each_dart([&](Dart d) {
      if (pos.has(d)) m.position[d] = pos.get(d);
    });
  }
  m.resize_flags();
  const EmbeddingField* e = f.find(kFlagEmbedding);
  if (!e) return m;
  if (e->orbit().size() != 0)
    throw Error(ErrorCode::Schema,
                "the embedding \"flag\" must be on the orbit type <> (one value per dart), not " +
                    e->orbit().str(),
                where);
  m.map.for_each_dart([&](Dart d) {
    if (!e->has(d)) return;
    const nlohmann::json v = e->value_json(d);
    if (v.is_boolean())
      m.flag[d] = v.get<bool>() ? 1 : 0;
    else if (v.is_number_unsigned())
      m.flag[d] = v.get<uint32_t>();
    else if (v.is_number_integer() && v.get<long long>() >= 0)
      m.flag[d] = static_cast<uint32_t>(v.get<long long>());
    else
      throw Error(ErrorCode::Schema,
                  "a flag is a boolean or a non-negative integer, not " + v.dump(),
                  where + (where.empty() ? "" : ": ") + "dart " + std::to_string(d));
  });
  return m;
}

EmbeddedMap to_embedded_map(const FlaggedMap& m) {
  EmbeddedMap f(m.map);
  EmbeddingField e = EmbeddingField::of_json(kFlagEmbedding, OrbitType{});
  m.map.for_each_dart([&](Dart d) {
    const uint32_t v = d < m.flag.size() ? m.flag[d] : 0;
    e.json->set_dart(m.map, d, v <= 1 ? nlohmann::json(v == 1) : nlohmann::json(v));
  });
  f.fields.push_back(std::move(e));
  if (m.positioned()) {
    PositionEmbedding& pos = f.add_position();
    for (Dart v : orbit_representatives(m.map, pos.orbit_type())) pos.set(m.map, v, m.position[v]);
  }
  return f;
}

}  // namespace gmr::replace
