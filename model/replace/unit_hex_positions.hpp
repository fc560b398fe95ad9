// Positions of a connected mesh of combinatorial hexahedra laid out as unit cubes (a polycube
// built by make_polycube, or any refinement of one): a traversal from dart 0, placed at the
// origin with its edge, face and third edge along x, y and z, carries a position and a frame
// (u1: its edge, u2: its face, u3: the third axis) to every dart:
//   alpha_0: position + u1 * length, u1 reversed;  alpha_1: u1 and u2 swapped;
//   alpha_2: u2 and u3 swapped;                     alpha_3: u3 reversed.
// The result is the polycube itself or its mirror image, translated (a valid embedding either
// way). `length` is the edge length.
#pragma once
#include "model/replace/flagged_map.hpp"

namespace gmr::replace {

// Throws Error(InvalidMap) when the map is not a 3-G-map or two paths give a vertex different
// positions (the map is not a mesh of unit cubes).
std::vector<Vec3> unit_hex_positions(const Map& g, double length = 1.0);

}  // namespace gmr::replace
