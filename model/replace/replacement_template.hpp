// A pattern's interior compiled for repeated replacements (Damiand & Nivoliers 2022 §5.1–5.2, the
// G-map reading of cell_replacement.hpp). The isomorphism f of a match maps the k-th labelled dart
// of the pattern's boundary, from its start dart, to the k-th labelled dart of the cell's
// (docs/query-replace.md, Replacement), so a matched cell is given by its boundary darts in label
// order, and everything the replacement writes is known from the pattern alone:
//  * the interior darts are numbered 0..k-1 (their copies are k consecutive new darts);
//  * per dimension 0..i and interior dart, its alpha-neighbour as an interior dart, except for the
//    boundary neighbours of alpha_{i-1}, listed apart as the relinks (interior dart, b-th boundary
//    dart in label order, whose copy is f of it): a replacement writes each link array once, in
//    dart order, and then the relinks;
//  * per interior dart, its flag and its vertex: the vertex of the b-th boundary dart (it keeps the
//    target's position) or an interior vertex placed by mean value coordinates (§5.2), given as
//    weights on boundary darts in label order;
//  * the boundary's word from the start dart (flagged_word.hpp), with which a cell traversed from
//    the dart matched to the start is checked when no lookup was made (replace_only.hpp).
// A replacement is then one pass of array writes (cell_replacement.hpp), with no per-cell tables.
#pragma once
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "model/replace/flagged_word.hpp"
#include "model/replace/pattern.hpp"

namespace gmr::replace {

struct ReplacementTemplate {
  static constexpr uint32_t kInterior = UINT32_MAX;
  int cell_dim = 2;
  uint32_t interior = 0;  // k: darts copied per half-cell
  uint32_t boundary = 0;  // |B|: boundary darts of a matched cell, in label order
  // link[t][j]: the alpha_t-neighbour of interior dart j (< interior), t = 0..cell_dim; for a
  // boundary neighbour (t = cell_dim - 1 only), j itself, overwritten by the relink.
  std::array<std::vector<uint32_t>, 4> link;
  std::vector<std::pair<uint32_t, uint32_t>>
      relinks;  // (interior dart j, boundary rank b) of alpha_{i-1}
  // The same per interior dart: b, or kInterior when alpha_{i-1} stays in the interior.
  std::vector<uint32_t> relink_rank;
  std::vector<uint32_t> flag;  // per interior dart
  // The interior darts at a boundary vertex (j, boundary rank b) and at an interior vertex (j, v).
  std::vector<std::pair<uint32_t, uint32_t>> at_boundary_vertex, at_interior_vertex;
  // The same per interior dart: b (< boundary) at a boundary vertex, boundary + v at interior
  // vertex v.
  std::vector<uint32_t> vertex_source;
  // The boundary ranks whose positions a replacement reads (each boundary vertex's first dart).
  std::vector<uint32_t> vertex_reads;
  // Per interior vertex: its weights on boundary darts in label order (empty: the origin, for a
  // pattern without geometry).
  std::vector<std::vector<std::pair<uint32_t, double>>> weights;
  // W(B, start) with flags: per boundary dart in label order, its flag and the labels (1-based) of
  // its cell_dim neighbours.
  Word word;
};

// start: the local index of the pattern's boundary dart whose label order the template uses (its
// minimal word's start, pattern_store.hpp).
ReplacementTemplate compile_replacement(const Pattern& p, uint32_t start);

}  // namespace gmr::replace
