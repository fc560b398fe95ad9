// The position embedding: vertex coordinates of a mesh-like map.
//
// Name "position", orbit type the vertex orbit <1,...,n> of an n-G-map (<1,2> for surfaces), one
// Vec3 per vertex. In gmr.gmap files (JSON-valued embeddings) a position is the array [x, y, z].
#pragma once
#include <optional>
#include <string>

#include "model/core/gmap_file.hpp"
#include "model/core/vec3.hpp"

namespace gmr {

inline constexpr const char* kPositionName = "position";

using PositionEmbedding = Embedding<Vec3>;

// A map with vertex positions (what OFF/OBJ describe).
struct PositionedMap {
  Map map{2};
  PositionEmbedding position{kPositionName, OrbitType{1, 2}};
};

// The vertex orbit type <1..n> of an n-G-map.
OrbitType vertex_orbit_type(const Map& g);

// Positions as a JSON embedding: one [x, y, z] per orbit that has a value.
JsonEmbedding position_to_json(const Map& g, const PositionEmbedding& pos);
// Why a JSON value is not a position (an array of 3 finite numbers), or nullopt when it is one.
std::optional<std::string> position_value_problem(const nlohmann::json& v);
// The typed view of a JSON embedding: every value must be an array of 3 finite numbers
// (Error(Schema) naming the embedding and a dart of the offending orbit otherwise).
PositionEmbedding position_from_json(const Map& g, const JsonEmbedding& e);

// gmr.gmap content <-> positioned map. `to_positioned` requires a "position" embedding
// (Error(Schema) when there is none).
GMapFile to_gmap_file(const PositionedMap& m);
PositionedMap to_positioned(const GMapFile& f);

}  // namespace gmr
