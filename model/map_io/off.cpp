#include "model/map_io/off.hpp"

#include <charconv>
#include <cmath>

#include "model/map_io/atomic_write.hpp"
#include "model/map_io/line_tokens.hpp"
#include "model/map_io/read_file.hpp"

namespace gmr::io {

namespace {

struct Line {
  size_t number;                         // 1-based
  std::vector<std::string_view> tokens;  // comment stripped
};

// The next non-empty statement, or false at end of text.
class OffLexer {
 public:
  explicit OffLexer(std::string_view text) : text_(text) {}
  bool next(Line& line) {
    while (pos_ < text_.size()) {
      size_t end = text_.find('\n', pos_);
      if (end == std::string_view::npos) end = text_.size();
      const std::string_view raw = text_.substr(pos_, end - pos_);
      pos_ = end + 1;
      ++number_;
      line.number = number_;
      line.tokens = line_tokens(raw);
      if (!line.tokens.empty()) return true;
    }
    return false;
  }
  size_t last_line() const { return number_; }

 private:
  std::string_view text_;
  size_t pos_ = 0;
  size_t number_ = 0;
};

bool to_uint(std::string_view t, uint64_t& x) {
  auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), x);
  return ec == std::errc() && p == t.data() + t.size();
}

bool to_double(std::string_view t, double& x) {
  auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), x);
  return ec == std::errc() && p == t.data() + t.size() && std::isfinite(x);
}

std::string quoted(std::string_view t) { return "\"" + std::string(t) + "\""; }

// The OFF header keyword [ST][C][N][4]OFF (Princeton OFF, as CGAL reads it): vertex lines carry
// x y z [w] (4: homogeneous), then a normal (N: 3 numbers), a colour (C: 3 or 4 numbers, RGB[A])
// and texture coordinates (ST: 2 numbers). Normals, colours and texture coordinates are read and
// dropped: the map keeps positions only.
struct OffHeader {
  bool known = false, texture = false, colour = false, normal = false, homogeneous = false;

  size_t fixed() const { return (homogeneous ? 4 : 3) + (normal ? 3 : 0) + (texture ? 2 : 0); }
  bool accepts(size_t n) const {
    return colour ? (n == fixed() + 3 || n == fixed() + 4) : n == fixed();
  }
  std::string value_counts() const {
    return colour ? std::to_string(fixed() + 3) + " or " + std::to_string(fixed() + 4)
                  : std::to_string(fixed());
  }
  std::string vertex_layout() const {
    return std::string(homogeneous ? "x y z w" : "x y z") + (normal ? " nx ny nz" : "") +
           (colour ? " r g b [a]" : "") + (texture ? " s t" : "");
  }
  std::string value_name(size_t a) const {
    const size_t coords = homogeneous ? 4 : 3;
    if (a < coords) return std::string("coordinate ") + "xyzw"[a];
    if (normal && a < coords + 3) return "a normal component";
    return "a colour or texture component";
  }
};

OffHeader parse_header(std::string_view word) {
  OffHeader h;
  if (word.size() < 3 || word.substr(word.size() - 3) != "OFF") return h;
  std::string_view prefix = word.substr(0, word.size() - 3);
  auto take = [&](std::string_view flag, bool& on) {
    if (prefix.substr(0, flag.size()) == flag) {
      on = true;
      prefix.remove_prefix(flag.size());
    }
  };
  take("ST", h.texture);
  take("C", h.colour);
  take("N", h.normal);
  take("4", h.homogeneous);
  h.known = prefix.empty();
  return h;
}

}  // namespace

FaceList parse_off(std::string_view text, const std::string& source,
                   std::vector<size_t>* face_lines, std::vector<size_t>* vertex_lines) {
  auto where = [&](size_t line) {
    return (source.empty() ? "line " : source + ":") + std::to_string(line);
  };
  auto fail = [&](size_t line, const std::string& msg) -> Error {
    return Error(ErrorCode::Parse, msg, where(line));
  };
  OffLexer lex(text);
  Line line;
  auto need = [&](const std::string& what) {
    if (!lex.next(line))
      throw fail(lex.last_line() == 0 ? 1 : lex.last_line(),
                 "unexpected end of file: expected " + what);
  };
  need("the header \"OFF\"");
  const OffHeader header = parse_header(line.tokens[0]);
  if (!header.known)
    throw fail(line.number,
               "expected the header \"[ST][C][N][4]OFF\", found " + quoted(line.tokens[0]));
  std::vector<std::string_view> counts(line.tokens.begin() + 1, line.tokens.end());
  if (!counts.empty() && counts[0] == "BINARY")
    throw fail(line.number, "binary OFF files are not supported");
  size_t counts_line = line.number;
  if (counts.empty()) {
    need("the counts line \"vertices faces [edges]\"");
    counts = line.tokens;
    counts_line = line.number;
  }
  if (counts.size() < 2 || counts.size() > 3)
    throw fail(counts_line,
               "expected the counts \"vertices faces [edges]\" (2 or 3 integers), found " +
                   std::to_string(counts.size()) + " value(s)");
  uint64_t c[3] = {0, 0, 0};
  for (size_t k = 0; k < counts.size(); ++k)
    if (!to_uint(counts[k], c[k]) || c[k] >= UINT32_MAX)
      throw fail(counts_line, "expected a non-negative integer count, found " + quoted(counts[k]));
  const uint64_t nv = c[0], nf = c[1];
  FaceList fl;
  const size_t cap = 1u << 20;
  fl.vertices.reserve(std::min<uint64_t>(nv, cap));
  fl.faces.reserve(std::min<uint64_t>(nf, cap));
  if (vertex_lines) vertex_lines->clear();
  if (face_lines) face_lines->clear();
  for (uint64_t v = 0; v < nv; ++v) {
    need("vertex " + std::to_string(v) + " of " + std::to_string(nv) + " (\"" +
         header.vertex_layout() + "\")");
    if (!header.accepts(line.tokens.size()))
      throw fail(line.number, "expected a vertex \"" + header.vertex_layout() + "\" (" +
                                  header.value_counts() + " numbers), found " +
                                  std::to_string(line.tokens.size()) + " value(s)");
    double values[16] = {};
    for (size_t a = 0; a < line.tokens.size(); ++a)
      if (!to_double(line.tokens[a], values[a]))
        throw fail(line.number, "expected a finite number for " + header.value_name(a) +
                                    ", found " + quoted(line.tokens[a]));
    Vec3 p{values[0], values[1], values[2]};
    if (header.homogeneous) {  // 4OFF: x y z w, the point (x/w, y/w, z/w)
      if (values[3] == 0)
        throw fail(line.number, "homogeneous coordinate w = 0 (a point at infinity)");
      for (size_t a = 0; a < 3; ++a) p[a] /= values[3];
    }
    fl.vertices.push_back(p);
    if (vertex_lines) vertex_lines->push_back(line.number);
  }
  for (uint64_t f = 0; f < nf; ++f) {
    need("face " + std::to_string(f) + " of " + std::to_string(nf) + " (\"k v1 ... vk\")");
    uint64_t k = 0;
    if (!to_uint(line.tokens[0], k))
      throw fail(line.number,
                 "expected the number of vertices of a face, found " + quoted(line.tokens[0]));
    if (k < 3)
      throw fail(line.number, "a face needs at least 3 vertices, found " + std::to_string(k));
    if (line.tokens.size() < k + 1)
      throw fail(line.number, "the face announces " + std::to_string(k) + " vertices but lists " +
                                  std::to_string(line.tokens.size() - 1));
    const size_t extra = line.tokens.size() - 1 - k;
    if (extra != 0 && extra != 1 && extra != 3 && extra != 4)
      throw fail(line.number, "expected " + std::to_string(k) +
                                  " vertex indices and an optional colour (1, 3 or 4 "
                                  "numbers), found " +
                                  std::to_string(extra) + " extra value(s)");
    for (size_t e = 0; e < extra; ++e) {
      double x;
      if (!to_double(line.tokens[1 + k + e], x))
        throw fail(line.number, "expected a colour component (a number), found " +
                                    quoted(line.tokens[1 + k + e]));
    }
    std::vector<uint32_t> face(k);
    for (size_t p = 0; p < k; ++p) {
      uint64_t idx = 0;
      if (!to_uint(line.tokens[1 + p], idx))
        throw fail(line.number, "expected a vertex index, found " + quoted(line.tokens[1 + p]));
      if (idx >= nv)
        throw fail(line.number, "vertex index " + std::to_string(idx) + " out of range (" +
                                    std::to_string(nv) + " vertices, 0.." +
                                    std::to_string(static_cast<int64_t>(nv) - 1) + ")");
      face[p] = static_cast<uint32_t>(idx);
    }
    for (size_t p = 0; p < k; ++p)
      if (face[p] == face[(p + 1) % k])
        throw fail(line.number, "degenerate face: vertex " + std::to_string(face[p]) +
                                    " repeated consecutively");
    fl.faces.push_back(std::move(face));
    if (face_lines) face_lines->push_back(line.number);
  }
  if (lex.next(line))
    throw fail(line.number, "unexpected content after the last face (the counts announce " +
                                std::to_string(nv) + " vertices and " + std::to_string(nf) +
                                " faces)");
  fl.num_edges = static_cast<size_t>(c[2]);
  return fl;
}

EmbeddedMap read_off(std::string_view text, const std::string& source) {
  std::vector<size_t> face_lines, vertex_lines;
  const FaceList fl = parse_off(text, source, &face_lines, &vertex_lines);
  return map_from_file_faces(fl, {source, face_lines, vertex_lines});
}

EmbeddedMap read_off_file(const std::filesystem::path& path) {
  return read_off(read_text_file(path), path.string());
}

std::string format_coordinate(double x) {
  char buf[64];
  auto [p, ec] = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, p);
}

std::string face_list_lines(const FaceList& fl, const std::string& vertex_tag,
                            const std::string& face_tag, uint32_t index_base) {
  std::string out;
  for (const Vec3& p : fl.vertices)
    out += vertex_tag + format_coordinate(p[0]) + " " + format_coordinate(p[1]) + " " +
           format_coordinate(p[2]) + "\n";
  for (const auto& face : fl.faces) {
    out += face_tag.empty() ? std::to_string(face.size()) : face_tag;
    for (uint32_t v : face) out += " " + std::to_string(v + index_base);
    out += "\n";
  }
  return out;
}

std::string write_off(const FaceList& fl) {
  std::string out = "OFF\n" + std::to_string(fl.vertices.size()) + " " +
                    std::to_string(fl.faces.size()) + " " + std::to_string(fl.num_edges) + "\n";
  return out + face_list_lines(fl, "", "", 0);
}

std::string write_off(const Map& g, const PositionEmbedding& pos) {
  return write_off(face_list_from_map(g, pos));
}

void write_off_file(const std::filesystem::path& path, const Map& g, const PositionEmbedding& pos) {
  write_file_atomic(path, write_off(g, pos));
}

}  // namespace gmr::io
