// Face lists ("polygon soups" with shared vertices): the content of OFF and OBJ files, and their
// correspondence with 2-G-maps carrying positions.
//
//  * face list -> map: surface_from_faces (builders.hpp) links the faces' darts and 2-sews the
//    sides that share an edge; edges used by more than two faces and pinched vertices are rejected
//    with Error(NonManifold). Positions go to the vertex orbit <1,2>. A vertex used by no face has
//    no dart and is dropped.
//  * map -> face list: one vertex per <1,2>-orbit (numbered in increasing order of their smallest
//    dart), one face per <0,1>-orbit, listed by increasing smallest dart. A face is the cycle of
//    the vertices met along alpha_1 o alpha_0 from its starting dart. The starting dart is chosen
//    by the parity of a BFS from dart 0 (darts at even distance start their faces), which orients
//    all faces of an orientable surface consistently; on a non-orientable surface some
//    neighbouring faces necessarily disagree.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "model/core/builders.hpp"
#include "model/core/position.hpp"
#include "model/core/vec3.hpp"

namespace gmr::io {

struct FaceList {
  std::vector<Vec3> vertices;
  std::vector<std::vector<uint32_t>> faces;
  size_t num_edges = 0;  // informative (OFF counts line); 0 when unknown
};

// Requires a valid 2-G-map whose faces are closed polygons (no 0- or 1-free dart) with at least 3
// sides, and a position on every vertex. Throws Error(Usage) for another kind or dimension,
// Error(InvalidMap) for an invalid map or an open face, Error(Schema) for a missing position or a
// face with fewer than 3 sides, Error(NonManifold) for a map a face list cannot describe
// faithfully (a face through one vertex twice, two edges joining the same two vertices), each
// naming a dart.
FaceList face_list_from_map(const Map& g, const PositionEmbedding& pos);

// Builds the 2-G-map (dimension opt.n) of the face list with positions on <1,2>. Errors of
// surface_from_faces propagate (Error(NonManifold) naming the edge or vertex, Error(Schema) naming
// the face).
EmbeddedMap map_from_face_list(const FaceList& fl, const SurfaceOptions& opt = {});

// Where a file's faces and vertices are: the 1-based line of each face and vertex of a face list.
struct FaceLines {
  std::string source;
  std::vector<size_t> face_lines, vertex_lines;
};
// map_from_face_list for a face list read from a file (OFF, OBJ): the builder's errors are
// located "<source>:<line>" at the offending face or vertex, a non-manifold edge naming the lines
// of all its faces.
EmbeddedMap map_from_file_faces(const FaceList& fl, const FaceLines& file,
                                const SurfaceOptions& opt = {});

}  // namespace gmr::io
