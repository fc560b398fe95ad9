#include "model/expr/embedded_map.hpp"

#include <cmath>

#include "model/core/error.hpp"
#include "model/core/orbit.hpp"

namespace gmr::expr {

EmbeddingField* EmbeddedMap::find(std::string_view name) {
  for (auto& f : fields)
    if (f.name() == name) return &f;
  return nullptr;
}

const EmbeddingField* EmbeddedMap::find(std::string_view name) const {
  for (const auto& f : fields)
    if (f.name() == name) return &f;
  return nullptr;
}

namespace {

bool finite_number(const nlohmann::json& v) { return v.is_number() && std::isfinite(v.get<double>()); }

}  // namespace

EmbeddedMap to_embedded_map(const GMapFile& f) {
  EmbeddedMap m;
  m.map = f.map;
  for (const JsonEmbedding& e : f.embeddings) {
    EmbeddingField field{3, Embedding<Vec3>(e.name(), e.orbit_type())};
    int arity = 0;
    for (Dart rep : orbit_representatives(f.map, e.orbit_type())) {
      if (!e.has(rep)) continue;
      const nlohmann::json& v = e.get(rep);
      const std::string where = "embedding '" + e.name() + "', dart " + std::to_string(rep);
      int a = 0;
      Vec3 x{0, 0, 0};
      if (finite_number(v)) {
        a = 1;
        x[0] = v.get<double>();
      } else if (v.is_array() && v.size() == 3 && finite_number(v[0]) && finite_number(v[1]) && finite_number(v[2])) {
        a = 3;
        for (size_t k = 0; k < 3; ++k) x[k] = v[k].get<double>();
      } else {
        throw Error(ErrorCode::Schema,
                    "rule applications carry numeric embeddings only (a number or [x, y, z]); found " + v.dump(),
                    where);
      }
      if (arity != 0 && a != arity)
        throw Error(ErrorCode::Schema, "the embedding mixes numbers and triples", where);
      arity = a;
      field.values.set(f.map, rep, x);
    }
    field.arity = arity == 0 ? 3 : arity;
    m.fields.push_back(std::move(field));
  }
  return m;
}

GMapFile to_gmap_file(const EmbeddedMap& m) {
  GMapFile f;
  f.map = m.map;
  for (const EmbeddingField& field : m.fields) {
    JsonEmbedding e(field.name(), field.orbit());
    for (Dart rep : orbit_representatives(m.map, field.orbit())) {
      if (!field.values.has(rep)) continue;
      const Vec3& x = field.values.get(rep);
      e.set(m.map, rep, field.arity == 1 ? nlohmann::json(x[0]) : nlohmann::json::array({x[0], x[1], x[2]}));
    }
    f.embeddings.push_back(std::move(e));
  }
  return f;
}

}  // namespace gmr::expr
