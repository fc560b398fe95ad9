// Wavefront OBJ surface meshes in and out.
//
// Input: "v x y z [w]" vertices (also the common "v x y z r g b" with vertex colours; only x y z
// are kept) and "f v1 v2 v3 ..." faces of at least 3 vertices, each vertex "v", "v/vt", "v//vn" or
// "v/vt/vn" with 1-based indices, negative ones counting back from the last vertex read so far.
// Texture coordinates, normals, groups, objects, smoothing groups, materials, lines, points and
// free-form statements are read and dropped; any other statement is an error. Every problem is
// Error(Parse) located "<source>:<line>"; the faces become a 2-G-map with positions as for OFF
// (face_list.hpp, non-manifold input rejected by name).
//
// Output: a 2-G-map with positions: "v x y z" per vertex, "f i j k ..." per face (1-based indices),
// vertices and faces as in face_list_from_map (face_list.hpp). Written atomically.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>

#include "model/map_io/face_list.hpp"

namespace gmr::io {

FaceList parse_obj(std::string_view text, const std::string& source = {},
                   FaceLines* lines = nullptr);
EmbeddedMap read_obj(std::string_view text, const std::string& source = {});

std::string write_obj(const FaceList& fl);
std::string write_obj(const Map& g, const PositionEmbedding& pos);
void write_obj_file(const std::filesystem::path& path, const Map& g, const PositionEmbedding& pos);

}  // namespace gmr::io
