#include "model/io/obj.hpp"

#include "model/io/atomic_write.hpp"
#include "model/io/off.hpp"

namespace gmr::io {

std::string write_obj(const FaceList& fl) {
  std::string out = "# written by gmr: " + std::to_string(fl.vertices.size()) + " vertices, " +
                    std::to_string(fl.faces.size()) + " faces\n";
  for (const Vec3& p : fl.vertices)
    out += "v " + format_coordinate(p[0]) + " " + format_coordinate(p[1]) + " " + format_coordinate(p[2]) + "\n";
  for (const auto& face : fl.faces) {
    out += "f";
    for (uint32_t v : face) out += " " + std::to_string(v + 1);
    out += "\n";
  }
  return out;
}

std::string write_obj(const GMap& g, const PositionEmbedding& pos) { return write_obj(face_list_from_map(g, pos)); }

void write_obj_file(const std::filesystem::path& path, const GMap& g, const PositionEmbedding& pos) {
  write_file_atomic(path, write_obj(g, pos));
}

}  // namespace gmr::io
