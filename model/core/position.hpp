// The position embedding: vertex coordinates of a mesh-like map.
//
// Name "position" (kPositionName, embedded_map.hpp), orbit type the vertex orbit <1,...,n> of an
// n-G-map (<1,2> for surfaces), one Vec3 per vertex. In gmr.gmap files a position is the array
// [x, y, z].
#pragma once
#include <optional>
#include <string>

#include "model/core/embedded_map.hpp"
#include "model/core/vec3.hpp"

namespace gmr {

using PositionEmbedding = Embedding<Vec3>;

// The vertex orbit type <1..n> of an n-G-map.
OrbitType vertex_orbit_type(const Map& g);

// Why a JSON value is not a position (an array of 3 finite numbers), or nullopt when it is one.
std::optional<std::string> position_value_problem(const nlohmann::json& v);

}  // namespace gmr
