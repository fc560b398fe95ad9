#include "model/replace/flagged_map.hpp"

#include "model/core/error.hpp"

namespace gmr::replace {

size_t FlaggedMap::flagged() const {
  size_t n = 0;
  map.for_each_dart([&](Dart d) { n += d < flag.size() && flag[d] != 0; });
  return n;
}

FlaggedMap flagged_map(const GMapFile& f, const std::string& where) {
  FlaggedMap m{f.map, {}};
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
  return f;
}

}  // namespace gmr::replace
