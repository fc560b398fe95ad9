// Voxel sets for polycubes (make_polycube, builders.hpp), format "gmr.voxels" version 1:
//   {"format": "gmr.voxels", "version": 1, "voxels": [[x, y, z], ...]}
// Coordinates are integers in [-2^20, 2^20]; a duplicate voxel is an Error(Schema) at its path.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "model/core/builders.hpp"
#include "model/map_io/json_reader.hpp"

namespace gmr::io {

std::vector<Voxel> read_voxels_json(std::string_view text, const std::string& source = {});
std::vector<Voxel> voxels_from_json(const JsonAt& doc);
std::vector<Voxel> read_voxels_json_file(const std::filesystem::path& path);

}  // namespace gmr::io
