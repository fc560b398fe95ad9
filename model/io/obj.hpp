// Wavefront OBJ output of a 2-G-map with positions: "v x y z" per vertex, "f i j k ..." per face
// (1-based indices), vertices and faces as in face_list_from_map (face_list.hpp). Written
// atomically.
#pragma once
#include <filesystem>
#include <string>

#include "model/io/face_list.hpp"

namespace gmr::io {

std::string write_obj(const FaceList& fl);
std::string write_obj(const GMap& g, const PositionEmbedding& pos);
void write_obj_file(const std::filesystem::path& path, const GMap& g, const PositionEmbedding& pos);

}  // namespace gmr::io
