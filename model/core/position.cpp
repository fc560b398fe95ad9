#include "model/core/position.hpp"

#include <cmath>

#include "model/core/orbit.hpp"

namespace gmr {

OrbitType vertex_orbit_type(const Map& g) {
  if (g.dimension() < 1)
    throw Error(ErrorCode::Range, "a 0-G-map has no vertex orbit with positions");
  return OrbitType::range(1, g.dimension());
}

std::optional<std::string> position_value_problem(const nlohmann::json& v) {
  if (!v.is_array() || v.size() != 3)
    return "a position must be an array [x, y, z], found " + v.dump();
  for (size_t a = 0; a < 3; ++a)
    if (!v[a].is_number() || !std::isfinite(v[a].get<double>()))
      return "a position coordinate must be a finite number, found " + v[a].dump();
  return std::nullopt;
}

}  // namespace gmr
