// A pattern's interior compiled for repeated replacements (Damiand & Nivoliers 2022 §5.1–5.2, the
// G-map reading of cell_replacement.hpp). The isomorphism f of a match maps the k-th labelled dart
// of the pattern's minimal word to the k-th labelled dart of the cell's (docs/query-replace.md,
// Replacement), so a matched cell is given by its boundary darts in label order, and everything
// the replacement writes is known from the pattern alone:
//  * the interior darts are numbered 0..k-1 (their copies are k consecutive new darts);
//  * per interior dart and dimension 0..i, its alpha-neighbour: another interior dart, or (only
//    for alpha_{i-1}) the b-th boundary dart in label order, whose copy is f of it;
//  * per interior dart, its flag and its vertex: the vertex of the b-th boundary dart (it keeps the
//    target's position) or an interior vertex placed by mean value coordinates (§5.2), given as
//    weights on boundary darts in label order.
// A replacement is then one pass of array writes (query_replace.cpp), with no per-cell tables.
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "model/replace/pattern.hpp"

namespace gmr::replace {

struct ReplacementTemplate {
  int cell_dim = 2;
  uint32_t interior = 0;  // k: darts copied per half-cell
  uint32_t boundary = 0;  // |B|: boundary darts of a matched cell, in label order
  // link[j * (cell_dim + 1) + t]: the alpha_t-neighbour of interior dart j, as an interior index
  // (< interior) or interior + b for the b-th boundary dart in label order.
  std::vector<uint32_t> link;
  std::vector<uint32_t> flag;  // per interior dart
  // Per interior dart: an interior vertex index (< weights.size()) or kOnBoundary | b.
  std::vector<uint32_t> vertex;
  static constexpr uint32_t kOnBoundary = uint32_t(1) << 31;
  // Per interior vertex: its weights on boundary darts in label order (empty: the origin, for a
  // pattern without geometry).
  std::vector<std::vector<std::pair<uint32_t, double>>> weights;
};

// order: the local indices of p.boundary in label order from the start dart chosen for p (its
// minimal word's start, pattern_store.hpp).
ReplacementTemplate compile_replacement(const Pattern& p, const std::vector<uint32_t>& order);

}  // namespace gmr::replace
