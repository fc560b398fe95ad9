// e-patterns (Damiand & Nivoliers 2022 §4.1): split an edge into k edges. In a G-map every dart
// pair (d, alpha_0 d) of the edge's <0,2,...,n>-orbit gets 2(k-1) new darts in a chain
// d - a_1 - b_1 - ... - b_{k-1} - alpha_0 d (alpha_0 and alpha_1 alternating); alpha_j for j >= 2
// links the chains as it links their end darts. Old darts keep their vertex and their flag (the
// paper's split convention read for G-maps); new darts are unflagged. With positions, the new
// vertices are evenly spaced along the segment.
#pragma once
#include <vector>

#include "model/replace/flagged_map.hpp"

namespace gmr::replace {

// Splits the edge of d into k >= 1 edges (k = 1: nothing): split_edges on that one edge. Throws
// Error(InvalidMap), before any change, when a dart of the edge is 0-free. Returns the number of
// darts added.
size_t split_edge(FlaggedMap& m, Dart d, unsigned k);
// Splits every listed edge (one dart each) into k, with the link, flag and position arrays grown
// once and no per-edge tables: the same map up to isomorphism as splitting the edges one after the
// other (the new darts are numbered in another order). Throws Error(Usage) when two darts name the
// same edge. Returns the number of darts added.
size_t split_edges(FlaggedMap& m, const std::vector<Dart>& edges, unsigned k);
// Splits every edge of the map into k: split_edges on all edges, found without traversing them
// (every dart pair (x, alpha_0 x) is split). On a map without deleted darts, the k - 1 new darts
// next to dart x on its chain are numbered from x (first + (k - 1) x onwards), so every new link is
// computed from x's own links in one sequential pass; with deleted darts, the pairs are taken in
// dart order as split_edges numbers them. Returns the number of darts added.
size_t split_all_edges(FlaggedMap& m, unsigned k);

}  // namespace gmr::replace
