#include "model/replace/configurations.hpp"

#include <algorithm>

#include "model/core/builders.hpp"
#include "model/core/error.hpp"
#include "model/replace/edge_split.hpp"

namespace gmr::replace {

namespace {

// Every non-empty subset of `edges` (one dart per edge) split in 2 on a copy of `base`.
ConfigurationSet subsets(std::string name, int cell_dim, const Map& base,
                         const std::vector<Dart>& edges) {
  ConfigurationSet set;
  set.generator = std::move(name);
  set.cell_dim = cell_dim;
  const size_t k = edges.size();
  for (uint32_t mask = 1; mask < (1u << k); ++mask) {
    Configuration c;
    c.map.map = base;
    c.map.flag.assign(base.capacity(), 1);
    for (size_t e = 0; e < k; ++e)
      if (mask >> e & 1) {
        c.split.push_back(static_cast<int>(e));
        split_edge(c.map, edges[e], 2);
      }
    set.configurations.push_back(std::move(c));
  }
  return set;
}

// The edges of the polygon of dart 0 in cyclic order: one dart each, alpha_1 then alpha_0 steps.
std::vector<Dart> polygon_edges(const Map& g) {
  std::vector<Dart> edges;
  Dart d = 0;
  do {
    edges.push_back(d);
    d = g.alpha(1, g.alpha(0, d));
  } while (d != 0);
  return edges;
}

}  // namespace

namespace {

// The cube's faces as corner cycles (corners numbered by coordinate bits).
const std::vector<std::vector<uint32_t>> kHexFaces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                                      {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};

// Flags a dart iff its vertex is a corner (0..7) and its edge lies on a cube edge: its other end is
// a corner or the midpoint (8 + e) of a cube edge e at that corner.
void flag_corners(FlaggedMap& m, const std::vector<uint32_t>& vertex,
                  const std::vector<std::array<int, 2>>& edges) {
  m.resize_flags();
  const Map& g = m.map;
  g.for_each_dart([&](Dart d) {
    const uint32_t v = vertex[d], w = vertex[g.alpha(0, d)];
    const bool on_edge =
        w < 8 || (w < 20 && (edges[w - 8][0] == int(v) || edges[w - 8][1] == int(v)));
    m.flag[d] = v < 8 && on_edge ? 1 : 0;
  });
}

// hex-conformal: every non-empty set of split edges, and every subset of the faces whose 4 edges
// are split cut into 4 quads, built directly as a face list: corners 0..7, edge midpoints 8..19
// (cube_edges() order), face centres 20..25. A dart is flagged iff its vertex is a corner and its
// edge lies on a cube edge (docs/query-replace.md, Flags).
ConfigurationSet hex_conformal() {
  const auto edges = cube_edges();
  auto edge_index = [&](uint32_t a, uint32_t b) {
    for (size_t e = 0; e < edges.size(); ++e)
      if ((edges[e][0] == int(a) && edges[e][1] == int(b)) ||
          (edges[e][0] == int(b) && edges[e][1] == int(a)))
        return e;
    throw Error(ErrorCode::Range, "not a cube edge");
  };
  // Positions on the unit cube: corners by their coordinate bits, midpoints, face centres.
  std::array<Vec3, 26> point;
  for (uint32_t v = 0; v < 8; ++v)
    point[v] = {double(v & 1), double(v >> 1 & 1), double(v >> 2 & 1)};
  for (size_t e = 0; e < 12; ++e)
    for (int k = 0; k < 3; ++k)
      point[8 + e][k] = (point[edges[e][0]][k] + point[edges[e][1]][k]) / 2;
  for (size_t f = 0; f < 6; ++f)
    for (int k = 0; k < 3; ++k) {
      point[20 + f][k] = 0;
      for (uint32_t c : kHexFaces[f]) point[20 + f][k] += point[c][k] / 4;
    }
  ConfigurationSet set;
  set.generator = "hex-conformal";
  set.cell_dim = 3;
  for (uint32_t mask = 1; mask < (1u << 12); ++mask) {
    std::vector<uint32_t> full;  // faces whose 4 edges are split
    for (uint32_t f = 0; f < 6; ++f) {
      bool all = true;
      for (size_t i = 0; i < 4; ++i)
        all &= (mask >> edge_index(kHexFaces[f][i], kHexFaces[f][(i + 1) % 4]) & 1) != 0;
      if (all) full.push_back(f);
    }
    for (uint32_t cut = 0; cut < (1u << full.size()); ++cut) {
      std::vector<std::vector<uint32_t>> faces;
      std::vector<int> cut_faces;
      for (uint32_t f = 0; f < 6; ++f) {
        const auto& c = kHexFaces[f];
        const auto pos = std::find(full.begin(), full.end(), f);
        const bool is_cut = pos != full.end() && (cut >> (pos - full.begin()) & 1);
        auto mid = [&](size_t i) {
          return static_cast<uint32_t>(8 + edge_index(c[i], c[(i + 1) % 4]));
        };
        if (is_cut) {
          cut_faces.push_back(static_cast<int>(f));
          for (size_t i = 0; i < 4; ++i) faces.push_back({c[i], mid(i), 20 + f, mid((i + 3) % 4)});
        } else {
          std::vector<uint32_t> poly;
          for (size_t i = 0; i < 4; ++i) {
            poly.push_back(c[i]);
            if (mask >> (mid(i) - 8) & 1) poly.push_back(mid(i));
          }
          faces.push_back(poly);
        }
      }
      Configuration conf;
      std::vector<uint32_t> vertex;
      conf.map.map = surface_from_faces(faces, 26, {}, &vertex);
      flag_corners(conf.map, vertex, edges);
      conf.map.position.resize(conf.map.map.capacity());
      conf.map.map.for_each_dart([&](Dart d) { conf.map.position[d] = point[vertex[d]]; });
      for (int e = 0; e < 12; ++e)
        if (mask >> e & 1) conf.split.push_back(e);
      for (int f : cut_faces) conf.split.push_back(100 + f);  // faces cut in 4: 100 + face index
      set.configurations.push_back(std::move(conf));
    }
  }
  return set;
}

// marching-cubes: every non-constant inside/outside labelling of the cube's corners; the edges
// between differently labelled corners are split (vertices 8..19), each face is cut by segments
// joining its cut points (2 cuts: one segment; 4 cuts: two segments cutting off one opposite
// corner pair, both resolutions generated), §7.2. The map is the volume's boundary after the face
// step: 654 configurations. `split` lists the inside corners, then 100 + f for each 4-cut face
// resolved by cutting off its corners 1 and 3 (instead of 0 and 2).
ConfigurationSet marching_cubes() {
  const auto edges = cube_edges();
  auto edge_index = [&](uint32_t a, uint32_t b) -> uint32_t {
    for (size_t e = 0; e < edges.size(); ++e)
      if ((edges[e][0] == int(a) && edges[e][1] == int(b)) ||
          (edges[e][0] == int(b) && edges[e][1] == int(a)))
        return static_cast<uint32_t>(e);
    throw Error(ErrorCode::Range, "not a cube edge");
  };
  ConfigurationSet set;
  set.generator = "marching-cubes";
  set.cell_dim = 3;
  for (uint32_t inside = 1; inside < 255; ++inside) {
    auto cut = [&](uint32_t a, uint32_t b) { return ((inside >> a) ^ (inside >> b)) & 1; };
    std::vector<uint32_t> ambiguous;  // faces with 4 cuts
    for (uint32_t f = 0; f < 6; ++f) {
      uint32_t n = 0;
      for (size_t i = 0; i < 4; ++i) n += cut(kHexFaces[f][i], kHexFaces[f][(i + 1) % 4]);
      if (n == 4) ambiguous.push_back(f);
    }
    for (uint32_t res = 0; res < (1u << ambiguous.size()); ++res) {
      std::vector<std::vector<uint32_t>> faces;
      Configuration conf;
      for (uint32_t v = 0; v < 8; ++v)
        if (inside >> v & 1) conf.split.push_back(static_cast<int>(v));
      for (uint32_t f = 0; f < 6; ++f) {
        const auto& c = kHexFaces[f];
        auto mid = [&](size_t i) { return 8 + edge_index(c[i % 4], c[(i + 1) % 4]); };
        std::vector<size_t> cuts;
        for (size_t i = 0; i < 4; ++i)
          if (cut(c[i], c[(i + 1) % 4])) cuts.push_back(i);
        if (cuts.empty()) {
          faces.push_back(c);
        } else if (cuts.size() == 2) {  // mid(i), c[i+1], ..., c[j], mid(j) and the rest
          const size_t i = cuts[0], j = cuts[1];
          std::vector<uint32_t> a{mid(i)}, b{mid(j)};
          for (size_t k = i + 1; k <= j; ++k) a.push_back(c[k % 4]);
          a.push_back(mid(j));
          for (size_t k = j + 1; k <= i + 4; ++k) b.push_back(c[k % 4]);
          b.push_back(mid(i));
          faces.push_back(a);
          faces.push_back(b);
        } else {  // 4 cuts: triangles at corners r and r+2, a hexagon between
          const auto pos = std::find(ambiguous.begin(), ambiguous.end(), f) - ambiguous.begin();
          const size_t r = (res >> pos & 1) ? 1 : 0;
          if (r) conf.split.push_back(100 + static_cast<int>(f));
          faces.push_back({c[r], mid(r), mid(r + 3)});
          faces.push_back({c[r + 2], mid(r + 2), mid(r + 1)});
          faces.push_back({mid(r), c[r + 1], mid(r + 1), mid(r + 2), c[(r + 3) % 4], mid(r + 3)});
        }
      }
      std::vector<uint32_t> vertex;
      conf.map.map = surface_from_faces(faces, 20, {}, &vertex);
      flag_corners(conf.map, vertex, edges);
      set.configurations.push_back(std::move(conf));
    }
  }
  return set;
}

}  // namespace

std::vector<std::string> configuration_generators() {
  return {"square-edges", "triangle-edges", "hex-edges", "hex-conformal", "marching-cubes"};
}

std::vector<std::array<int, 2>> cube_edges() {
  std::vector<std::array<int, 2>> e;
  for (int a = 0; a < 8; ++a)
    for (int b = a + 1; b < 8; ++b)
      if (__builtin_popcount(static_cast<unsigned>(a ^ b)) == 1) e.push_back({a, b});
  return e;
}

ConfigurationSet generate_configurations(std::string_view generator) {
  if (generator == "square-edges" || generator == "triangle-edges") {
    const Map g = make_polygon(generator == "square-edges" ? 4 : 3);
    return subsets(std::string(generator), 2, g, polygon_edges(g));
  }
  if (generator == "hex-conformal") return hex_conformal();
  if (generator == "marching-cubes") return marching_cubes();
  if (generator == "hex-edges") {
    std::vector<uint32_t> vertex;
    const Map g = surface_from_faces(
        {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}}, 8, {},
        &vertex);
    std::vector<Dart> edges;
    for (const auto& [a, b] : cube_edges()) {
      Dart found = kNoDart;
      g.for_each_dart([&](Dart d) {
        if (found == kNoDart && vertex[d] == uint32_t(a) && vertex[g.alpha(0, d)] == uint32_t(b))
          found = d;
      });
      edges.push_back(found);
    }
    return subsets("hex-edges", 3, g, edges);
  }
  std::string known;
  for (const auto& n : configuration_generators()) known += (known.empty() ? "" : ", ") + n;
  throw Error(
      ErrorCode::Usage,
      "unknown configuration generator \"" + std::string(generator) + "\" (known: " + known + ")",
      "--configurations");
}

}  // namespace gmr::replace
