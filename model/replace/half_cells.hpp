// The number of half-cells a query-replace replaces (query_replace.hpp, replacement_room): per
// i-cell, one for a cell with one half-cell (<0..i-1>-orbit) and two for a cell of an n-G-map,
// n > i, with two (alpha_{i+1} not free: the cell is replaced on both sides, cell_replacement.hpp).
// Counted over the half-cells, each once: one sweep with a bit per dart. A half-face is walked
// as its cycle (alpha_0, alpha_1 alternating), a volume as its half-faces joined by alpha_2; a
// half-cell whose walk meets a free dart is traversed breadth-first instead.
#pragma once
#include <cstddef>

#include "model/core/map.hpp"

namespace gmr::replace {

// i = 2 (faces) or 3 (volumes) of a G-map of dimension i or i + 1.
size_t count_half_cells(const Map& g, int i);

// Both counts of a 3-G-map in one sweep: every half-face lies in exactly one volume, so the volume
// sweep counts the half-faces it walks (when a volume meets a free dart below 3 and is traversed
// instead, the half-faces are counted by a sweep of their own).
struct HalfFacesAndVolumes {
  size_t faces = 0, volumes = 0;
};
HalfFacesAndVolumes count_half_faces_and_volumes(const Map& g);

}  // namespace gmr::replace
