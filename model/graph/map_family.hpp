// Exhaustive enumeration of small maps up to isomorphism: the bounded universe on which rules are
// validated semantically (checker/semantic.hpp) and property tests draw small maps.
//
//  * `connected_maps(n, kind, k)`: every connected n-G-map (labels 0..n, all involutions,
//    C(i,j) for i+2 <= j) or n-O-map (beta_1 any permutation, beta_2..n involutions,
//    C on (1..n)_{+2}) with exactly k darts, one per isomorphism class (canonical dedup by
//    the BFS-word signature of signature.hpp). Brute force over the involutions/permutations of
//    k darts: meant for k <= 6 (n <= 2) — larger sizes grow as (#involutions(k))^(n+1).
//  * `map_family(n, kind, max_darts)`: every map with 1..max_darts darts up to isomorphism, i.e.
//    the multisets of connected classes of total size <= max_darts, sorted by size (so the first
//    counterexample found is a smallest one), with their D-graphs.
#pragma once
#include <vector>

#include "model/core/map.hpp"
#include "model/graph/dgraph.hpp"

namespace gmr::graph {

std::vector<Map> connected_maps(int n, MapKind kind, size_t darts);

struct MapFamily {
  int n = 0;
  MapKind kind = MapKind::GMap;
  size_t max_darts = 0;
  std::vector<Map> maps;
  std::vector<DGraph> graphs;  // to_dgraph(maps[k])
};
MapFamily map_family(int n, MapKind kind, size_t max_darts);

}  // namespace gmr::graph
