#include "model/map_io/obj.hpp"

#include <charconv>
#include <cmath>

#include "model/map_io/atomic_write.hpp"
#include "model/map_io/line_tokens.hpp"
#include "model/map_io/off.hpp"

namespace gmr::io {

namespace {

bool is_dropped_statement(std::string_view k) {
  static constexpr std::string_view kDropped[] = {
      "vt",     "vn",         "vp",        "g",     "o",      "s",        "mg",
      "usemtl", "mtllib",     "l",         "p",     "cstype", "deg",      "bmat",
      "step",   "curv",       "curv2",     "surf",  "parm",   "trim",     "hole",
      "scrv",   "sp",         "end",       "con",   "bevel",  "c_interp", "d_interp",
      "lod",    "shadow_obj", "trace_obj", "ctech", "stech",  "maplib",   "usemap"};
  for (std::string_view d : kDropped)
    if (k == d) return true;
  return false;
}

}  // namespace

FaceList parse_obj(std::string_view text, const std::string& source, FaceLines* lines) {
  auto fail = [&](size_t line, const std::string& msg) {
    return Error(ErrorCode::Parse, msg,
                 (source.empty() ? "line " : source + ":") + std::to_string(line));
  };
  FaceList fl;
  FaceLines where;
  size_t pos = 0, number = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view raw = text.substr(pos, end - pos);
    pos = end + 1;
    ++number;
    const std::vector<std::string_view> t = line_tokens(raw);
    if (t.empty()) continue;
    if (t[0] == "v") {
      if (t.size() != 4 && t.size() != 5 && t.size() != 7)
        throw fail(number, "expected a vertex \"v x y z [w]\" or \"v x y z r g b\", found " +
                               std::to_string(t.size() - 1) + " value(s)");
      Vec3 p{};
      for (size_t k = 1; k < t.size(); ++k) {
        double x = 0;
        auto [q, ec] = std::from_chars(t[k].data(), t[k].data() + t[k].size(), x);
        if (ec != std::errc() || q != t[k].data() + t[k].size() || !std::isfinite(x))
          throw fail(number, "expected a finite number, found \"" + std::string(t[k]) + "\"");
        if (k <= 3) p[k - 1] = x;
      }
      fl.vertices.push_back(p);
      where.vertex_lines.push_back(number);
    } else if (t[0] == "f") {
      if (t.size() < 4)
        throw fail(number,
                   "a face needs at least 3 vertices, found " + std::to_string(t.size() - 1));
      std::vector<uint32_t> face;
      for (size_t k = 1; k < t.size(); ++k) {
        const std::string_view ref = t[k].substr(0, t[k].find('/'));
        long long idx = 0;
        auto [q, ec] = std::from_chars(ref.data(), ref.data() + ref.size(), idx);
        if (ec != std::errc() || q != ref.data() + ref.size() || idx == 0)
          throw fail(
              number,
              "expected a vertex index (1-based, or negative from the last vertex), found \"" +
                  std::string(t[k]) + "\"");
        const long long nv = static_cast<long long>(fl.vertices.size());
        const long long v = idx > 0 ? idx - 1 : nv + idx;
        if (v < 0 || v >= nv)
          throw fail(number, "vertex index " + std::to_string(idx) + " out of range (" +
                                 std::to_string(nv) + " vertices read so far)");
        face.push_back(static_cast<uint32_t>(v));
      }
      for (size_t p = 0; p < face.size(); ++p)
        if (face[p] == face[(p + 1) % face.size()])
          throw fail(number, "degenerate face: vertex " + std::to_string(face[p] + 1) +
                                 " repeated consecutively");
      fl.faces.push_back(std::move(face));
      where.face_lines.push_back(number);
    } else if (!is_dropped_statement(t[0])) {
      throw fail(number, "unknown OBJ statement \"" + std::string(t[0]).substr(0, 40) + "\"");
    }
  }
  if (lines) {
    where.source = source;
    *lines = std::move(where);
  }
  return fl;
}

EmbeddedMap read_obj(std::string_view text, const std::string& source) {
  FaceLines lines;
  const FaceList fl = parse_obj(text, source, &lines);
  return map_from_file_faces(fl, lines);
}

std::string write_obj(const FaceList& fl) {
  std::string out = "# written by gmr: " + std::to_string(fl.vertices.size()) + " vertices, " +
                    std::to_string(fl.faces.size()) + " faces\n";
  return out + face_list_lines(fl, "v ", "f", 1);
}

std::string write_obj(const Map& g, const PositionEmbedding& pos) {
  return write_obj(face_list_from_map(g, pos));
}

void write_obj_file(const std::filesystem::path& path, const Map& g, const PositionEmbedding& pos) {
  write_file_atomic(path, write_obj(g, pos));
}

}  // namespace gmr::io
