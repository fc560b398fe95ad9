#include "model/core/position.hpp"

#include <cmath>

#include "model/core/orbit.hpp"

namespace gmr {

OrbitType vertex_orbit_type(const Map& g) {
  if (g.dimension() < 1) throw Error(ErrorCode::Range, "a 0-G-map has no vertex orbit with positions");
  return OrbitType::range(1, g.dimension());
}

JsonEmbedding position_to_json(const Map& g, const PositionEmbedding& pos) {
  JsonEmbedding out(pos.name(), pos.orbit_type());
  for (Dart rep : orbit_representatives(g, pos.orbit_type())) {
    if (!pos.has(rep)) continue;
    const Vec3& p = pos.get(rep);
    out.set(g, rep, nlohmann::json::array({p[0], p[1], p[2]}));
  }
  return out;
}

std::optional<std::string> position_value_problem(const nlohmann::json& v) {
  if (!v.is_array() || v.size() != 3) return "a position must be an array [x, y, z], found " + v.dump();
  for (size_t a = 0; a < 3; ++a)
    if (!v[a].is_number() || !std::isfinite(v[a].get<double>()))
      return "a position coordinate must be a finite number, found " + v[a].dump();
  return std::nullopt;
}

PositionEmbedding position_from_json(const Map& g, const JsonEmbedding& e) {
  PositionEmbedding out(e.name(), e.orbit_type());
  for (Dart rep : orbit_representatives(g, e.orbit_type())) {
    if (!e.has(rep)) continue;
    const nlohmann::json& v = e.get(rep);
    if (auto problem = position_value_problem(v))
      throw Error(ErrorCode::Schema, *problem, "embedding '" + e.name() + "', dart " + std::to_string(rep));
    out.set(g, rep, Vec3{v[0].get<double>(), v[1].get<double>(), v[2].get<double>()});
  }
  return out;
}

GMapFile to_gmap_file(const PositionedMap& m) {
  GMapFile f;
  f.map = m.map;
  f.embeddings.push_back(position_to_json(m.map, m.position));
  return f;
}

PositionedMap to_positioned(const GMapFile& f) {
  const JsonEmbedding* e = f.find(kPositionName);
  if (!e) throw Error(ErrorCode::Schema, "the map has no \"position\" embedding (vertex coordinates)");
  PositionedMap m;
  m.map = f.map;
  m.position = position_from_json(m.map, *e);
  return m;
}

}  // namespace gmr
