// Builders of standard objects. Every builder returns a valid map; free darts are loops.
// `n` is the dimension of the produced G-map (higher dimensions carry loops), at least the
// object's own dimension.
#pragma once
#include <array>
#include <vector>

#include "model/core/map.hpp"

namespace gmr {

// A face-list surface: faces as vertex-index cycles. Edges shared by two face sides are 2-sewn.
// Throws Error(NonManifold) when an edge is used by more than two face sides (naming the edge and
// the faces), and Error(Schema) for degenerate faces (fewer than 3 vertices, repeated consecutive
// vertex, out-of-range index). Vertices whose fan is not a single disc (bow-ties) are rejected
// with Error(NonManifold) when `reject_nonmanifold_vertices` is set (the default for OFF input).
struct SurfaceOptions {
  int n = 2;
  bool reject_nonmanifold_vertices = true;
};
// vertex_of_dart (optional output): for every dart, the index of its vertex in the face list.
Map surface_from_faces(const std::vector<std::vector<uint32_t>>& faces, size_t num_vertices,
                       const SurfaceOptions& opt = {},
                       std::vector<uint32_t>* vertex_of_dart = nullptr);

Map make_free_edge(int n = 2);                 // 2 darts, 0-linked
Map make_polygon(size_t k, int n = 2);         // 2k darts: one open face
Map make_tetrahedron(int n = 2);               // closed surface, 24 darts
Map make_cube(int n = 2);                      // closed surface, 48 darts
Map make_square_pyramid(int n = 2);            // closed surface, 32 darts
Map make_prism(size_t k, int n = 2);           // closed surface over a k-gon
Map make_grid(size_t w, size_t h, int n = 2);  // open w x h grid of quads, 8wh darts

// Two cubes (3-G-map volumes) 3-sewn along a face: 96 darts (inference paper, §3.3).
Map make_stacked_cubes();

// Polycube: one cube volume (48 darts) per voxel, 3-sewn along the faces of face-adjacent
// voxels. Duplicate voxels are rejected (Error(Schema)).
using Voxel = std::array<int, 3>;
Map make_polycube(const std::vector<Voxel>& voxels);
// Menger sponge voxels at `level` (20^level voxels).
std::vector<Voxel> menger_voxels(int level);
// One iteration of the (l, m, k)-Menger operation on a unit cube (Menger polycubes, Richaume et al.
// 2019, cited by the inference paper §9.2.2): the (2l+1) x (2m+1) x (2k+1) grid without the voxels
// having at least two odd coordinates, i.e. l, m, k unit holes through the cube along the three
// axes, one unit apart. (1, 1, 1) is menger_voxels(1); (2, 2, 2) has 81 voxels.
std::vector<Voxel> menger_polycube_voxels(int l, int m, int k);

// A closed orientable surface of genus 1 (a torus) as a grid of w x h quads with wrap-around.
Map make_torus(size_t w, size_t h, int n = 2);

// The map as an n-G-map (n-O-map) for n >= its dimension: the same darts and links, every new
// dimension free (loops). A surface lifted to dimension 3 is a 3-G-map with one volume per
// connected component, so that rules written for volumes apply to it.
Map lift(const Map& g, int n);

// The O-map of the orientation class of dart `d` of a closed orientable G-map:
// beta_i = alpha_i o alpha_0 (i >= 1) restricted to the darts reachable from d by even words.
// Throws Error(InvalidMap) when the component is not orientable or has a free dart.
// keep_boundary: 2-free darts are allowed (surfaces with boundary) and give beta_2 loops (the
// graph form of a free dart in an O-map, thesis Def. 32). Other free darts are still refused:
// 0-/1-free darts (open polygons) have no orientation class, and an i-loop with i >= 3 cannot
// satisfy the O-map cycle constraint C(1,i) (beta_i beta_1 beta_i beta_1 (d) = beta_1^2(d) != d
// on a boundary face): Def. 32 O-maps have no 3-boundary — close the volume first (e.g.
// double_along_boundary in random_maps.hpp).
Map orient(const Map& g, Dart d = 0, bool keep_boundary = false);

}  // namespace gmr
