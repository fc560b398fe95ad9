// Adaptive hexahedral meshing by query-replace (Damiand & Nivoliers 2022 §7.1, Alg. 5): starting
// from one hexahedron (a box around the surface), level by level, the hexahedra of the finest
// level that meet the surface are cut into 2x2x2 with the patterns `split4` (faces) and `hex8`
// (volumes) of tools/data/patterns/hex-subdivision; the meshes stay balanced (Alg. 5's "more
// than one level finer than a neighbour", through faces, edges and vertices, as the authors' code
// balances through faces and edges): a coarser hexahedron sharing a vertex with one being refined
// is refined too, recursively. Refining a hexahedron: its edges that are not split yet are split
// in 2 (e-pattern), its faces are queried (those already cut by a finer neighbour match nothing),
// then the volume; the hexahedra of a level are cut coarsest first (a balance hexahedron before
// its finer neighbours, whose faces would otherwise cut its faces twice). Every dart of the new
// hexahedra is flagged (their corners, as the authors' code does). Hexahedra outside the surface
// are kept (the authors' code deletes them). Levels are read off the geometry: a hexahedron's level
// is log2(root size / its size), the hexahedra being axis-aligned boxes.
#pragma once
#include <functional>
#include <vector>

#include "model/replace/pattern_store.hpp"

namespace gmr::replace {

struct MeshingLevel {
  int level = 0;
  size_t volumes = 0;  // hexahedra after the level
  size_t face_replacements = 0;
  size_t volume_replacements = 0;
  size_t balanced = 0;  // hexahedra refined for the balance only
  double seconds = 0;   // CPU time of the level (the count of its volumes not included)
};

// Whether the axis-aligned box [lo, hi] meets the surface.
using BoxTest = std::function<bool(const Vec3& lo, const Vec3& hi)>;

// The unit cube hexahedron scaled to the box [lo, lo + size]^3, every dart flagged.
FlaggedMap box_hexahedron(const Vec3& lo, double size);

// Refines m (a mesh built by box_hexahedron, or refined by this function) `levels` times.
// store: the hex-subdivision patterns (unoriented mode).
std::vector<MeshingLevel> refine_adaptively(FlaggedMap& m, const PatternStore& store, int levels,
                                            const BoxTest& meets_surface);

}  // namespace gmr::replace
