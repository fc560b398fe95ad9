// v-patterns made from a closed cell boundary (Damiand & Nivoliers 2022 §6.4, §7.3: the conformal
// volume patterns are one per configuration class; the paper draws them, here they are built).
// The cone of a closed flagged 2-G-map surface S is the 3-G-map whose boundary is S and whose
// interior is one pyramid per face of S, all sharing one apex: every dart d of S gives four darts,
//   b(d) = d          on S (3-free, the flag of d),
//   t0(d)             on the triangle over d's edge, at d's vertex, on the base edge,
//   t1(d)             the same triangle, at d's vertex, on the edge to the apex,
//   t2(d)             the same triangle, at the apex, on the edge from d's vertex,
// with alpha_0 = (b(a0 d), t0(a0 d), t2(d), t1(d)), alpha_1 = (b(a1 d), t1(d), t0(d), t2(a0 d)),
// alpha_2 = (t0(d), b(d), t1(a1 d), t2(a1 d)) and alpha_3 = (b(d), t0(a2 d), t1(a2 d), t2(a2 d))
// for (b, t0, t1, t2). Each is an involution and alpha_i alpha_j (j >= i + 2) is one because S's
// alpha_0 alpha_2 is; the boundary successor abar_2(b(d)) = alpha_2 alpha_3 alpha_2 (b(d)) = b(a2
// d), so the boundary is S itself, with its orientation (b(d) = d keeps the parity of every dart).
// With positions on S, the apex is the mean of S's corners (its vertices with a flagged dart: the
// cell's corners, docs/query-replace.md, Flags; every vertex when nothing is flagged), each once,
// and the pattern gets mean value coordinates when it is made (§5.2).
#pragma once
#include <string>
#include <vector>

#include "model/replace/flagged_map.hpp"
#include "model/replace/flagged_word.hpp"
#include "model/replace/pattern.hpp"

namespace gmr::replace {

// Throws Error(InvalidMap) when the surface is not a closed 2-G-map without holes in its darts.
FlaggedMap cone_of_surface(const FlaggedMap& surface);

// The v-patterns of hex-conformal: one cone per configuration class in `mode` (the first
// configuration of each class in generation order), named "hex-<split edges>[-f<cut faces>]".
std::vector<Pattern> conformal_volume_patterns(Mode mode);

}  // namespace gmr::replace
