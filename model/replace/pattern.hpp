// Patterns (Damiand & Nivoliers 2022 §4): an f-pattern is a 2-G-map disc of faces, a v-pattern a
// 3-G-map ball of volumes, with dart flags. Its boundary (the n-free darts, boundary_graph.hpp) is
// the query; a matched cell gets the pattern's interior (the darts that are not n-free).
// Validated when made (the paper leaves it implicit): a valid connected n-G-map, n = 2 or 3, with
// no i-free dart for i < n (closed faces; closed volumes) and a non-empty connected boundary, so
// that the boundary successor exists everywhere and the boundary is one cycle (f) or one closed
// surface (v).
#pragma once
#include <string>
#include <vector>

#include "model/replace/boundary_graph.hpp"
#include "model/replace/flagged_map.hpp"
#include "model/replace/interior_geometry.hpp"

namespace gmr::replace {

struct Pattern {
  std::string name;
  FlaggedMap map;                 // an n-G-map; n = cell_dim
  int cell_dim = 2;               // 2: f-pattern (replaces faces), 3: v-pattern (volumes)
  std::vector<uint8_t> positive;  // orientation classes; empty when the pattern is not orientable
  BoundaryGraph boundary;         // the query
  size_t interior = 0;            // darts that are not n-free
  // Mean value coordinates of the interior vertices (empty without positions or orientation).
  std::vector<InteriorVertex> interior_vertices;
  // Precomputed for replacements: the interior darts in index order; per dart, its vertex (an
  // index into vertex_anchor); per vertex, one boundary dart of it (kNoDart: interior vertex).
  std::vector<Dart> interior_darts;
  std::vector<uint32_t> vertex_of;
  std::vector<Dart> vertex_anchor;

  const char* kind() const { return cell_dim == 2 ? "f-pattern" : "v-pattern"; }
};

// Throws Error(Schema) located at `name` when the map is not a pattern.
Pattern make_pattern(std::string name, FlaggedMap m);

}  // namespace gmr::replace
