// The direct hexahedral subdivision (Damiand & Nivoliers 2022 §7.1, "time-direct" of Table 1):
// every hexahedron of a 3-G-map cut into 2x2x2 hexahedra by hand-written code, without patterns,
// the baseline that query-replace (split edges, f-pattern, v-pattern) is measured against and
// validated by.
// Construction: a dart d of a hexahedron is a corner v with an edge (axis a1) and a face (axes a1,
// a2; a3 is the third edge at v). The sub-hexahedron at v has 48 darts, 8 per dart of the
// hexahedron at v: dart (d, w), w in {0,1}^3 its corner (bit k along axis a_{k+1}). Then
//   alpha_0(d, w) = (d, w ^ 1)                   (along a1)
//   alpha_1(d, w) = (alpha_1 d, w with bits 0, 1 swapped)
//   alpha_2(d, w) = (alpha_2 d, w with bits 1, 2 swapped)
//   alpha_3(d, w) = (alpha_3 d, w)               if w_3 = 0 (the face lies on the old face)
//                 = (alpha_2 alpha_1 alpha_0 alpha_1 alpha_2 d, w)   if w_3 = 1 (an inner face,
//                   shared with the sub-hexahedron across the middle plane normal to a3).
// The vertex of (d, w) is the corner, edge midpoint, face centre or cell centre spanned by the
// axes of w's set bits (averages of the old vertices). Every dart of the result is flagged (the
// new cells' corners, as the paper's Alg. 5 does).
#pragma once
#include "model/replace/flagged_map.hpp"

namespace gmr::replace {

// Throws Error(InvalidMap) unless m is a 3-G-map whose volumes are combinatorial hexahedra (every
// face a quadrangle, three edges at every corner of every volume).
FlaggedMap subdivide_hexahedra(const FlaggedMap& m);

}  // namespace gmr::replace
