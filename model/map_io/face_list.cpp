#include "model/map_io/face_list.hpp"

#include <algorithm>
#include <cstdio>
#include <map>

#include "model/core/orbit.hpp"
#include "model/core/validity.hpp"
#include "model/map_io/read_limits.hpp"

namespace gmr::io {

FaceList face_list_from_map(const Map& g, const PositionEmbedding& pos) {
  if (g.is_omap() || g.dimension() != 2)
    throw Error(ErrorCode::Usage, std::string("a face list needs a 2-G-map, not a ") +
                                      std::to_string(g.dimension()) + "-" +
                                      (g.is_omap() ? "O-map" : "G-map"));
  const ValidityReport report = check_validity(g, 1);
  if (!report.ok())
    throw Error(ErrorCode::InvalidMap,
                "the map is not a valid 2-G-map: " + to_text(report.violations.front()),
                "dart " + std::to_string(report.violations.front().at));
  FaceList fl;
  const Dart cap = g.capacity();
  // Vertices: <1,2>-orbits.
  std::vector<uint32_t> vertex_of(cap, UINT32_MAX);
  const OrbitType vtype{1, 2};
  for (Dart rep : orbit_representatives(g, vtype)) {
    if (!pos.has(rep))
      throw Error(ErrorCode::Schema, "vertex without a position", "dart " + std::to_string(rep));
    const auto v = static_cast<uint32_t>(fl.vertices.size());
    fl.vertices.push_back(pos.get(rep));
    for (Dart d : orbit(g, vtype, rep)) vertex_of[d] = v;
  }
  // Parity of a BFS over all links (per connected component).
  std::vector<uint8_t> parity(cap, 2);
  std::vector<Dart> queue;
  g.for_each_dart([&](Dart root) {
    if (parity[root] != 2) return;
    parity[root] = 0;
    queue.assign(1, root);
    for (size_t h = 0; h < queue.size(); ++h) {
      const Dart v = queue[h];
      for (int i = 0; i <= 2; ++i) {
        const Dart w = g.alpha(i, v);
        if (parity[w] == 2) {
          parity[w] = static_cast<uint8_t>(1 - parity[v]);
          queue.push_back(w);
        }
      }
    }
  });
  // Faces: <0,1>-orbits.
  for (Dart rep : orbit_representatives(g, OrbitType{0, 1})) {
    const Dart start = parity[rep] == 0 ? rep : g.alpha(0, rep);
    std::vector<uint32_t> face;
    Dart d = start;
    do {
      const Dart e = g.alpha(0, d);
      if (e == d || g.alpha(1, e) == e)
        throw Error(ErrorCode::InvalidMap, "open face: a polygon needs no 0- or 1-free dart",
                    "dart " + std::to_string(e == d ? d : e));
      face.push_back(vertex_of[d]);
      d = g.alpha(1, e);
    } while (d != start);
    if (face.size() < 3)
      throw Error(
          ErrorCode::Schema,
          "face with " + std::to_string(face.size()) + " side(s); a polygon needs at least 3",
          "dart " + std::to_string(rep));
    // Faithfulness: a face list names vertices, so a face through one vertex twice, or two edges
    // joining the same two vertices, would be read back as another map (found by the OFF round-
    // trip property, proptests/model_prop.cpp). Refused instead of written wrong.
    std::vector<uint32_t> sorted = face;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      throw Error(ErrorCode::NonManifold,
                  "a face passes twice through one vertex; a face list cannot describe it",
                  "dart " + std::to_string(rep));
    fl.faces.push_back(std::move(face));
  }
  // Every edge (<0,2>-orbit) must be the only one joining its two vertices.
  std::map<std::pair<uint32_t, uint32_t>, Dart> edge_of;
  for (Dart rep : orbit_representatives(g, OrbitType{0, 2})) {
    const uint32_t a = vertex_of[rep], b = vertex_of[g.alpha(0, rep)];
    const auto [it, fresh] = edge_of.emplace(std::minmax(a, b), rep);
    if (!fresh)
      throw Error(ErrorCode::NonManifold,
                  "two edges join the same two vertices (darts " + std::to_string(it->second) +
                      " and " + std::to_string(rep) + "); a face list would merge them",
                  "dart " + std::to_string(rep));
  }
  fl.num_edges = count_orbits(g, OrbitType{0, 2});
  return fl;
}

EmbeddedMap map_from_face_list(const FaceList& fl, const SurfaceOptions& opt) {
  std::vector<uint32_t> vertex_of_dart;
  EmbeddedMap m(surface_from_faces(fl.faces, fl.vertices.size(), opt, &vertex_of_dart));
  PositionEmbedding& position = m.add_position();
  for (Dart rep : orbit_representatives(m.map, position.orbit_type()))
    position.set(m.map, rep, fl.vertices[vertex_of_dart[rep]]);
  return m;
}

EmbeddedMap map_from_file_faces(const FaceList& fl, const FaceLines& file,
                                const SurfaceOptions& opt) {
  uint64_t darts = 0;  // two darts per face corner
  for (const auto& face : fl.faces) darts += 2 * face.size();
  check_dart_limit(darts, file.source);
  const std::string& source = file.source;
  const std::vector<size_t>& face_lines = file.face_lines;
  const std::vector<size_t>& vertex_lines = file.vertex_lines;
  auto where = [&](size_t line) {
    return (source.empty() ? "line " : source + ":") + std::to_string(line);
  };
  try {
    return map_from_face_list(fl, opt);
  } catch (const Error& e) {
    // Map the builder's location ("edge (u,v)", "vertex v", "face f") to file lines.
    unsigned long u = 0, v = 0;
    int used = 0;
    const std::string& loc = e.location();
    if (std::sscanf(loc.c_str(), "edge (%lu,%lu)%n", &u, &v, &used) == 2 &&
        used == static_cast<int>(loc.size())) {
      std::vector<size_t> lines;
      for (size_t f = 0; f < fl.faces.size(); ++f) {
        const auto& face = fl.faces[f];
        for (size_t p = 0; p < face.size(); ++p) {
          const uint32_t a = face[p], b = face[(p + 1) % face.size()];
          if ((a == u && b == v) || (a == v && b == u)) {
            lines.push_back(face_lines[f]);
            break;
          }
        }
      }
      std::string list;
      for (size_t l : lines) list += (list.empty() ? "" : ", ") + std::to_string(l);
      const size_t at = lines.size() > 2 ? lines[2] : (lines.empty() ? 1 : lines.back());
      throw Error(e.code(), e.message() + " on " + loc + ", faces at lines " + list, where(at));
    }
    if (std::sscanf(loc.c_str(), "vertex %lu%n", &u, &used) == 1 &&
        used == static_cast<int>(loc.size()) && u < vertex_lines.size())
      throw Error(e.code(), e.message() + " (" + loc + ")", where(vertex_lines[u]));
    if (std::sscanf(loc.c_str(), "face %lu%n", &u, &used) == 1 &&
        used == static_cast<int>(loc.size()) && u < face_lines.size())
      throw Error(e.code(), e.message(), where(face_lines[u]));
    throw Error(e.code(), e.message(), source.empty() ? loc : source + ": " + loc);
  }
}

}  // namespace gmr::io
