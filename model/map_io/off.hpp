// OFF (Object File Format) surface meshes in and out.
//
// Accepted input (one statement per line; '#' starts a comment anywhere on a line; blank lines and
// comment-only lines are skipped):
//   [ST][C][N][4]OFF         header; the counts may follow on the same line ("OFF 8 6 12");
//                            binary OFF is refused by name
//   nv nf [ne]               counts line; ne (edges) is optional and ignored
//   x y z [w] [n] [c] [st]   nv vertex lines of finite numbers: 3 coordinates (4OFF: 4,
//                            homogeneous), then per the header a normal (N, 3), a colour (C, 3 or
//                            4) and texture coordinates (ST, 2), read and dropped
//   k v_1 ... v_k [colour]   nf face lines: k >= 3 vertex indices in 0..nv-1, no vertex repeated
//                            consecutively; 0, 1, 3 or 4 trailing numbers (a colour) are ignored
// Anything after the last face is an error (the counts disagree with the file; CGAL's reader
// ignores it). Every malformed line is reported as Error(Parse)
// located "<source>:<line>", with what was expected. The faces are turned into a 2-G-map by
// surface_from_faces (face_list.hpp): an edge shared by more than two faces or a pinched vertex is
// rejected with the builder's Error(NonManifold), located at the file line of the offending face
// (or vertex) and naming the other faces' lines. Vertex positions go to the "position" embedding on
// <1,2>; vertices used by no face are dropped (no dart carries them).
//
// Output: from a valid 2-G-map with positions (face_list_from_map): "OFF", the counts line with
// the number of edges, one line per vertex (shortest round-trip decimal form) and per face.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>

#include "model/core/position.hpp"
#include "model/map_io/face_list.hpp"

namespace gmr::io {

// The face list of an OFF text, without building a map (errors located "<source>:<line>").
// `face_lines` (optional) receives the 1-based line of every face.
FaceList parse_off(std::string_view text, const std::string& source = {},
                   std::vector<size_t>* face_lines = nullptr,
                   std::vector<size_t>* vertex_lines = nullptr);

EmbeddedMap read_off(std::string_view text, const std::string& source = {});
EmbeddedMap read_off_file(const std::filesystem::path& path);

std::string write_off(const FaceList& fl);
std::string write_off(const Map& g, const PositionEmbedding& pos);
void write_off_file(const std::filesystem::path& path, const Map& g, const PositionEmbedding& pos);

// Shortest decimal text that reads back as the same double (std::to_chars).
std::string format_coordinate(double x);

// The vertex and face lines of a face list, as OFF and OBJ write them: per vertex, `vertex_tag`
// then its coordinates; per face, `face_tag` (or, when empty, its number of vertices) then its
// vertex indices counted from `index_base`.
std::string face_list_lines(const FaceList& fl, const std::string& vertex_tag,
                            const std::string& face_tag, uint32_t index_base);

}  // namespace gmr::io
