#include "model/core/builders.hpp"

#include <map>
#include <unordered_map>

#include "model/core/error.hpp"
#include "model/core/orbit.hpp"
#include "model/core/sew.hpp"

namespace gmr {

Map surface_from_faces(const std::vector<std::vector<uint32_t>>& faces, size_t num_vertices,
                       const SurfaceOptions& opt, std::vector<uint32_t>* vertex_of_dart) {
  if (opt.n < 2) throw Error(ErrorCode::Range, "a surface needs a G-map of dimension >= 2");
  Map g(opt.n);
  size_t total = 0;
  for (size_t f = 0; f < faces.size(); ++f) {
    const auto& face = faces[f];
    const std::string where = "face " + std::to_string(f);
    if (face.size() < 3) throw Error(ErrorCode::Schema, "a face needs at least 3 vertices", where);
    for (size_t p = 0; p < face.size(); ++p) {
      if (face[p] >= num_vertices)
        throw Error(ErrorCode::Schema,
                    "vertex index " + std::to_string(face[p]) + " out of range (" +
                        std::to_string(num_vertices) + " vertices)",
                    where);
      if (face[p] == face[(p + 1) % face.size()])
        throw Error(ErrorCode::Schema,
                    "degenerate edge: vertex " + std::to_string(face[p]) + " repeated", where);
    }
    total += 2 * face.size();
  }
  g.reserve(total);
  std::vector<uint32_t> vert;
  vert.reserve(total);
  // Edge (u,v), u<v  ->  the face sides using it: (dart at u, dart at v, face).
  struct Side {
    Dart at_u, at_v;
    size_t face;
  };
  std::unordered_map<uint64_t, std::vector<Side>> sides;
  sides.reserve(total / 2);
  for (size_t f = 0; f < faces.size(); ++f) {
    const auto& face = faces[f];
    const size_t k = face.size();
    const Dart first = g.add_darts(2 * k);
    // dart 2p: at vertex face[p] on edge p; dart 2p+1: at vertex face[p+1] on edge p.
    for (size_t p = 0; p < k; ++p) {
      const Dart a = first + static_cast<Dart>(2 * p), b = a + 1;
      const Dart next_a = first + static_cast<Dart>(2 * ((p + 1) % k));
      g.link(0, a, b);
      g.link(1, b, next_a);
      const uint32_t u = face[p], v = face[(p + 1) % k];
      vert.push_back(u);
      vert.push_back(v);
      const uint64_t key = (uint64_t(std::min(u, v)) << 32) | std::max(u, v);
      sides[key].push_back(u < v ? Side{a, b, f} : Side{b, a, f});
    }
  }
  for (const auto& [key, list] : sides) {
    if (list.size() > 2) {
      std::string fs;
      for (const auto& s : list) fs += (fs.empty() ? "" : ", ") + std::to_string(s.face);
      throw Error(
          ErrorCode::NonManifold,
          "non-manifold edge: used by " + std::to_string(list.size()) + " faces (" + fs + ")",
          "edge (" + std::to_string(key >> 32) + "," + std::to_string(key & 0xffffffffu) + ")");
    }
    if (list.size() == 2) {
      g.link(2, list[0].at_u, list[1].at_u);
      g.link(2, list[0].at_v, list[1].at_v);
    }
  }
  if (opt.reject_nonmanifold_vertices) {
    // A manifold vertex is one <1,2>-orbit; several orbits at one vertex index = a pinched vertex.
    std::vector<uint32_t> orbits_at(num_vertices, 0);
    ScopedMarker seen(g);
    std::vector<Dart> stack;
    const DimMask m = (1u << 1) | (1u << 2);
    for (Dart d = 0; d < g.capacity(); ++d) {
      if (seen.test(d)) continue;
      if (++orbits_at[vert[d]] > 1)
        throw Error(ErrorCode::NonManifold, "non-manifold vertex: its faces form more than one fan",
                    "vertex " + std::to_string(vert[d]));
      visit_orbit_marked(g, m, d, seen.id(), stack, [](Dart) {});
    }
  }
  if (vertex_of_dart) *vertex_of_dart = std::move(vert);
  return g;
}

Map make_free_edge(int n) {
  Map g(n);
  g.add_darts(2);
  g.link(0, 0, 1);
  return g;
}

Map make_polygon(size_t k, int n) {
  if (k < 1) throw Error(ErrorCode::Range, "a polygon needs at least one edge");
  if (n < 1) throw Error(ErrorCode::Range, "a polygon needs a G-map of dimension >= 1");
  Map g(n);
  g.add_darts(2 * k);
  for (size_t p = 0; p < k; ++p) {
    const auto a = static_cast<Dart>(2 * p);
    g.link(0, a, a + 1);
    g.link(1, a + 1, static_cast<Dart>(2 * ((p + 1) % k)));
  }
  return g;
}

static SurfaceOptions with_n(int n) {
  SurfaceOptions o;
  o.n = n;
  return o;
}

Map make_tetrahedron(int n) {
  return surface_from_faces({{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}}, 4, with_n(n));
}

// Unit-cube corners c = x + 2y + 4z.
static const std::vector<std::vector<uint32_t>> kCubeFaces = {
    {0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};

Map make_cube(int n) { return surface_from_faces(kCubeFaces, 8, with_n(n)); }

Map make_square_pyramid(int n) {
  return surface_from_faces({{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}}, 5,
                            with_n(n));
}

Map make_prism(size_t k, int n) {
  if (k < 3) throw Error(ErrorCode::Range, "a prism needs a base with at least 3 sides");
  std::vector<std::vector<uint32_t>> faces(2);
  for (size_t p = 0; p < k; ++p) {
    faces[0].push_back(static_cast<uint32_t>(k - 1 - p));
    faces[1].push_back(static_cast<uint32_t>(k + p));
    const auto a = static_cast<uint32_t>(p), b = static_cast<uint32_t>((p + 1) % k);
    faces.push_back({a, b, b + static_cast<uint32_t>(k), a + static_cast<uint32_t>(k)});
  }
  return surface_from_faces(faces, 2 * k, with_n(n));
}

Map make_grid(size_t w, size_t h, int n) {
  if (w < 1 || h < 1) throw Error(ErrorCode::Range, "a grid needs at least 1x1 quads");
  std::vector<std::vector<uint32_t>> faces;
  auto id = [&](size_t x, size_t y) { return static_cast<uint32_t>(y * (w + 1) + x); };
  for (size_t y = 0; y < h; ++y)
    for (size_t x = 0; x < w; ++x)
      faces.push_back({id(x, y), id(x + 1, y), id(x + 1, y + 1), id(x, y + 1)});
  return surface_from_faces(faces, (w + 1) * (h + 1), with_n(n));
}

Map make_torus(size_t w, size_t h, int n) {
  if (w < 3 || h < 3) throw Error(ErrorCode::Range, "a torus grid needs at least 3x3 quads");
  std::vector<std::vector<uint32_t>> faces;
  faces.reserve(w * h);
  auto id = [&](size_t x, size_t y) { return static_cast<uint32_t>((y % h) * w + (x % w)); };
  for (size_t y = 0; y < h; ++y)
    for (size_t x = 0; x < w; ++x)
      faces.push_back({id(x, y), id(x + 1, y), id(x + 1, y + 1), id(x, y + 1)});
  return surface_from_faces(faces, w * h, with_n(n));
}

Map make_polycube(const std::vector<Voxel>& voxels) {
  Map g(3);
  // A dart of a voxel cube is identified, in space, by (face centre, vertex, other end of its
  // edge) in doubled integer coordinates; the darts of two face-adjacent voxels with the same key
  // are the ones 3-sewing pairs.
  using Key = std::array<int, 9>;
  std::map<Key, Dart> first_side;
  std::map<Voxel, size_t> seen;
  std::vector<std::pair<Dart, Dart>> to_sew;
  for (size_t k = 0; k < voxels.size(); ++k) {
    const Voxel& vx = voxels[k];
    if (!seen.emplace(vx, k).second)
      throw Error(ErrorCode::Schema,
                  "duplicate voxel (" + std::to_string(vx[0]) + "," + std::to_string(vx[1]) + "," +
                      std::to_string(vx[2]) + ")",
                  "voxel " + std::to_string(k));
    std::vector<uint32_t> corner_of;
    Map cube = surface_from_faces(kCubeFaces, 8, with_n(3), &corner_of);
    const Dart base = g.add_darts(cube.capacity());
    for (int i = 0; i <= 2; ++i)
      for (Dart d = 0; d < cube.capacity(); ++d) g.set_alpha(i, base + d, base + cube.alpha(i, d));
    auto pos = [&](uint32_t c) {
      return std::array<int, 3>{2 * (vx[0] + int(c & 1)), 2 * (vx[1] + int((c >> 1) & 1)),
                                2 * (vx[2] + int((c >> 2) & 1))};
    };
    for (Dart d = 0; d < cube.capacity(); ++d) {
      // Face centre = mean of the face's 4 corners: the <0,1>-orbit has 8 darts, 2 per corner.
      std::array<int, 3> centre{0, 0, 0};
      for (Dart e : orbit(cube, OrbitType{0, 1}, d)) {
        auto p = pos(corner_of[e]);
        for (int a = 0; a < 3; ++a) centre[a] += p[a];
      }
      const auto p = pos(corner_of[d]), q = pos(corner_of[cube.alpha(0, d)]);
      Key key{centre[0] / 8, centre[1] / 8, centre[2] / 8, p[0], p[1], p[2], q[0], q[1], q[2]};
      auto [it, fresh] = first_side.emplace(key, base + d);
      if (!fresh) to_sew.emplace_back(it->second, base + d);
    }
  }
  for (auto [a, b] : to_sew)
    if (g.is_free(3, a)) sew(g, 3, a, b);
  return g;
}

std::vector<Voxel> menger_voxels(int level) {
  if (level < 0 || level > 5) throw Error(ErrorCode::Range, "Menger level must be in 0..5");
  std::vector<Voxel> cur{{0, 0, 0}};
  for (int l = 0; l < level; ++l) {
    std::vector<Voxel> next;
    for (const Voxel& v : cur)
      for (int x = 0; x < 3; ++x)
        for (int y = 0; y < 3; ++y)
          for (int z = 0; z < 3; ++z) {
            if ((x == 1) + (y == 1) + (z == 1) >= 2) continue;
            next.push_back({3 * v[0] + x, 3 * v[1] + y, 3 * v[2] + z});
          }
    cur = std::move(next);
  }
  return cur;
}

std::vector<Voxel> menger_polycube_voxels(int l, int m, int k) {
  if (l < 0 || m < 0 || k < 0 || l > 100 || m > 100 || k > 100)
    throw Error(ErrorCode::Range, "Menger polycube hole counts must be in 0..100");
  std::vector<Voxel> out;
  for (int x = 0; x <= 2 * l; ++x)
    for (int y = 0; y <= 2 * m; ++y)
      for (int z = 0; z <= 2 * k; ++z)
        if ((x % 2) + (y % 2) + (z % 2) < 2) out.push_back({x, y, z});
  return out;
}

Map make_stacked_cubes() { return make_polycube({{0, 0, 0}, {0, 0, 1}}); }

Map orient(const Map& g, Dart d, bool keep_boundary) {
  if (g.is_omap()) throw Error(ErrorCode::Usage, "orient expects a G-map");
  if (!g.alive(d)) throw Error(ErrorCode::Range, "no such dart", "dart " + std::to_string(d));
  const int n = g.dimension();
  if (n < 1) throw Error(ErrorCode::Range, "orient needs dimension >= 1");
  // Parity BFS over the connected component.
  std::unordered_map<Dart, int> parity{{d, 0}};
  std::vector<Dart> queue{d};
  for (size_t h = 0; h < queue.size(); ++h) {
    const Dart v = queue[h];
    for (int i = 0; i <= n; ++i) {
      const Dart w = g.alpha(i, v);
      if (w == v && keep_boundary && i == 2) continue;  // boundary: beta_2(v) = v below
      if (w == v)
        throw Error(ErrorCode::InvalidMap,
                    "cannot orient: dart is " + std::to_string(i) + "-free (open object)",
                    "dart " + std::to_string(v));
      auto [it, fresh] = parity.emplace(w, 1 - parity[v]);
      if (fresh)
        queue.push_back(w);
      else if (it->second == parity[v])
        throw Error(ErrorCode::InvalidMap, "cannot orient: the object is not orientable",
                    "darts " + std::to_string(v) + ", " + std::to_string(w));
    }
  }
  std::vector<Dart> even;
  for (Dart v : queue)
    if (parity[v] == 0) even.push_back(v);
  std::unordered_map<Dart, Dart> index;
  for (size_t k = 0; k < even.size(); ++k) index[even[k]] = static_cast<Dart>(k);
  Map o(n, MapKind::OMap);
  o.add_darts(even.size());
  for (size_t k = 0; k < even.size(); ++k)
    for (int i = 1; i <= n; ++i) {
      // A 2-free dart stays 2-free: alpha_2(alpha_0(d)) = alpha_0(d) then, since alpha_0 alpha_2
      // is an involution (cycle constraint), so the boundary is a beta_2 loop.
      const bool free_i = i == 2 && g.alpha(i, even[k]) == even[k];
      o.set_alpha(i, static_cast<Dart>(k),
                  free_i ? static_cast<Dart>(k) : index.at(g.alpha(i, g.alpha(0, even[k]))));
    }
  return o;
}

Map lift(const Map& g, int n) {
  if (n < g.dimension() || n >= kMaxDim)
    throw Error(ErrorCode::Usage, "cannot lift a " + std::to_string(g.dimension()) +
                                      "-map to dimension " + std::to_string(n) + " (expected " +
                                      std::to_string(g.dimension()) + ".." +
                                      std::to_string(kMaxDim - 1) + ")");
  Map out(n, g.kind());
  out.add_darts(g.capacity());
  for (int i = g.lowest_dim(); i <= g.dimension(); ++i)
    for (Dart d = 0; d < g.capacity(); ++d) out.set_alpha(i, d, g.alpha(i, d));
  for (Dart d = 0; d < g.capacity(); ++d)
    if (!g.alive(d)) out.remove_dart(d);
  return out;
}

}  // namespace gmr
