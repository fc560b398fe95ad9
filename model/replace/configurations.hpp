// Configuration generators for the exhaustiveness check (Damiand & Nivoliers 2022 §6.4): every
// configuration an application can meet, built as a flagged map whose cell is then signed and
// looked up. The original darts are flagged (corners on original edges), split darts unflagged.
//  * square-edges: a square face with a non-empty set of its 4 edges split in 2 (conformal
//    refinement's faces, §7.3: 15 configurations);
//  * triangle-edges: the same for a triangle (7 configurations);
//  * hex-edges: a hexahedron (the cube's surface as a 2-G-map volume) with a non-empty set of its
//    12 edges split in 2 (4095 configurations);
//  * hex-conformal: a hexahedron with a non-empty set of split edges, and any subset of its faces
//    whose 4 edges are split already cut into 4 quads (the configurations of conformal refinement,
//    §7.3: 6209). `split` lists the split edges, then 100 + f for each cut face f. With positions
//    on the unit cube (corners, edge midpoints, face centres);
//  * marching-cubes: the boundary of a hexahedron after the face step of marching cubes (§7.2) for
//    every non-constant corner labelling, both resolutions of each face with 4 cuts (654).
// Edges are numbered: polygons in cyclic order from dart 0; the cube by its vertex pairs (a, b),
// a < b, vertices numbered by coordinate bits x + 2y + 4z, in increasing order.
#pragma once
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "model/replace/flagged_map.hpp"

namespace gmr::replace {

struct Configuration {
  std::vector<int> split;  // the split edges (indices, increasing)
  FlaggedMap map;
  Dart cell = 0;  // a dart of the configuration's cell
};

struct ConfigurationSet {
  std::string generator;
  int cell_dim = 2;
  std::vector<Configuration> configurations;
};

std::vector<std::string> configuration_generators();
// Throws Error(Usage) naming the known generators for an unknown name.
ConfigurationSet generate_configurations(std::string_view generator);
// The cube's 12 edges as vertex pairs, in the numbering of hex-edges.
std::vector<std::array<int, 2>> cube_edges();

}  // namespace gmr::replace
