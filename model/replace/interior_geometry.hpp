// Geometry of replaced interiors (Damiand & Nivoliers 2022 §5.2): boundary vertices keep the
// target's positions; an interior vertex of a pattern is placed by generalized barycentric
// coordinates of the pattern's boundary vertices, precomputed once per pattern: mean value
// coordinates of the boundary polygon for f-patterns (Floater), of the boundary surface,
// fan-triangulated, for v-patterns (Ju, Schaefer & Warren 2005). Both reproduce affine maps: a
// target that is an affine image of the pattern gets the affine image of its interior.
// New vertices of split edges are placed at i/k along the edge.
#pragma once
#include <utility>
#include <vector>

#include "model/core/map.hpp"
#include "model/core/vec3.hpp"

namespace gmr::replace {

// One interior vertex: a dart of it and its weights on boundary darts (summing to 1).
struct InteriorVertex {
  Dart dart = kNoDart;
  std::vector<std::pair<Dart, double>> weights;
};

// position: per pattern dart; positive: the orientation classes (boundary faces of a v-pattern are
// walked from a dart of D+, so that the triangles are consistently oriented). Returns the interior
// vertices (vertex orbits without an n-free dart) with their coordinates.
std::vector<InteriorVertex> mean_value_coordinates(const Map& p, const std::vector<Vec3>& position,
                                                   const std::vector<uint8_t>& positive);

}  // namespace gmr::replace
