#include "model/core/embedded_map.hpp"

#include <cmath>

#include "model/core/error.hpp"
#include "model/core/orbit.hpp"
#include "model/core/position.hpp"

namespace gmr {

namespace {

// Integers above this lose precision as doubles: such values stay JSON.
constexpr double kLargestExactInteger = 9007199254740992.0;  // 2^53

bool exact_number(const nlohmann::json& v) {
  if (!v.is_number()) return false;
  const double x = v.get<double>();
  return std::isfinite(x) && (v.is_number_float() || std::fabs(x) <= kLargestExactInteger);
}

bool all_integers(const nlohmann::json& v) {
  if (v.is_array()) {
    for (const auto& x : v)
      if (!x.is_number_integer()) return false;
    return true;
  }
  return v.is_number_integer();
}

nlohmann::json number_json(double x, bool integral) {
  if (integral && std::nearbyint(x) == x && std::fabs(x) <= kLargestExactInteger)
    return nlohmann::json(static_cast<int64_t>(x));
  return nlohmann::json(x);
}

}  // namespace

std::optional<std::string> numeric_value_problem(const nlohmann::json& v, int& arity) {
  if (exact_number(v)) {
    arity = 1;
    return std::nullopt;
  }
  if (v.is_array() && v.size() == 3 && exact_number(v[0]) && exact_number(v[1]) &&
      exact_number(v[2])) {
    arity = 3;
    return std::nullopt;
  }
  return "a number or [x, y, z] is expected; found " + v.dump();
}

EmbeddingField EmbeddingField::numeric(std::string name, OrbitType orbit, int arity) {
  if (arity != 1 && arity != 3)
    throw Error(ErrorCode::Usage, "a numeric embedding has arity 1 or 3");
  EmbeddingField f{arity, Embedding<Vec3>(std::move(name), std::move(orbit)), std::nullopt, false};
  return f;
}

EmbeddingField EmbeddingField::of_json(std::string name, OrbitType orbit) {
  return EmbeddingField{0, Embedding<Vec3>(name, orbit), JsonEmbedding(name, orbit), false};
}

nlohmann::json EmbeddingField::value_json(Dart d) const {
  if (!is_numeric()) return json->get(d);
  const Vec3& x = values.get(d);
  if (arity == 1) return number_json(x[0], integral);
  return nlohmann::json::array(
      {number_json(x[0], integral), number_json(x[1], integral), number_json(x[2], integral)});
}

std::vector<EmbeddingIssue> EmbeddingField::check(const Map& g) const {
  return is_numeric() ? values.check(g) : json->check(g);
}

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

bool EmbeddedMap::has_position() const {
  const EmbeddingField* f = find(kPositionName);
  return f && f->arity == 3;
}

const Embedding<Vec3>& EmbeddedMap::position() const {
  const EmbeddingField* f = find(kPositionName);
  if (!f)
    throw Error(ErrorCode::Schema, "the map has no \"position\" embedding (vertex coordinates)");
  if (f->arity == 3) return f->values;
  for (Dart rep : orbit_representatives(map, f->orbit())) {
    if (!f->has(rep)) continue;
    const nlohmann::json v = f->value_json(rep);
    if (auto problem = position_value_problem(v))
      throw Error(ErrorCode::Schema, *problem,
                  "embedding '" + f->name() + "', dart " + std::to_string(rep));
  }
  throw Error(ErrorCode::Schema, "the \"position\" embedding does not hold [x, y, z] values");
}

Embedding<Vec3>& EmbeddedMap::position() {
  return const_cast<Embedding<Vec3>&>(std::as_const(*this).position());
}

EmbeddingField& EmbeddedMap::add_numeric(std::string name, OrbitType orbit, int arity) {
  if (find(name))
    throw Error(ErrorCode::Usage, "the map already has an embedding \"" + name + "\"");
  fields.push_back(EmbeddingField::numeric(std::move(name), std::move(orbit), arity));
  return fields.back();
}

Embedding<Vec3>& EmbeddedMap::add_position() {
  return add_numeric(kPositionName, vertex_orbit_type(map)).values;
}

EmbeddingField field_from_json(const Map& g, std::string name, OrbitType orbit,
                               const std::vector<std::pair<Dart, nlohmann::json>>& values) {
  int arity = 0;
  bool numeric = true, integral = true;
  for (const auto& [d, v] : values) {
    int a = 0;
    if (numeric_value_problem(v, a) || (arity != 0 && a != arity)) {
      numeric = false;
      break;
    }
    arity = a;
    integral = integral && all_integers(v);
  }
  if (!numeric) {
    EmbeddingField f = EmbeddingField::of_json(std::move(name), std::move(orbit));
    for (const auto& [d, v] : values) f.json->set(g, d, v);
    return f;
  }
  EmbeddingField f =
      EmbeddingField::numeric(std::move(name), std::move(orbit), arity == 0 ? 3 : arity);
  f.integral = integral && !values.empty();
  for (const auto& [d, v] : values)
    f.values.set(g, d,
                 f.arity == 1 ? Vec3{v.get<double>(), 0, 0}
                              : Vec3{v[0].get<double>(), v[1].get<double>(), v[2].get<double>()});
  return f;
}

}  // namespace gmr
