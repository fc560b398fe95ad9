#include "model/replace/cell_replacement.hpp"

#include "model/core/error.hpp"
#include "model/core/orbit.hpp"
#include "model/core/position.hpp"

namespace gmr::replace {

namespace {

// §5.2: a copied dart at a boundary vertex takes the target's position of that vertex; at an
// interior vertex, the pattern's mean value coordinates applied to the target's boundary positions
// (the origin when the pattern has no geometry).
void place_interior(FlaggedMap& target, const Pattern& p, const std::vector<Dart>& f, const std::vector<Dart>& copy,
                    const std::vector<Dart>& mirror) {
  const GMap& q = p.map.map;
  const OrbitType vertex = vertex_orbit_type(q);
  std::vector<Vec3> at(q.capacity(), Vec3{0, 0, 0});
  for (const InteriorVertex& v : p.interior_vertices) {
    Vec3 x{0, 0, 0};
    for (const auto& [b, w] : v.weights)
      for (int c = 0; c < 3; ++c) x[c] += w * target.position[f[b]][c];
    for (Dart y : orbit(q, vertex, v.dart)) at[y] = x;
  }
  for (Dart rep : orbit_representatives(q, vertex)) {
    const std::vector<Dart> darts = orbit(q, vertex, rep);
    for (Dart y : darts)
      if (f[y] != kNoDart) {
        for (Dart z : darts) at[z] = target.position[f[y]];
        break;
      }
  }
  q.for_each_dart([&](Dart x) {
    if (copy[x] == kNoDart) return;
    target.position[copy[x]] = at[x];
    if (!mirror.empty()) target.position[mirror[x]] = at[x];
  });
}

}  // namespace

size_t replace_cell(FlaggedMap& target, const Pattern& p, const std::vector<Dart>& f) {
  GMap& g = target.map;
  const GMap& q = p.map.map;
  const int i = p.cell_dim, n = g.dimension();
  if (n != i && n != i + 1)
    throw Error(ErrorCode::Usage, "a " + std::string(p.kind()) + " replaces cells of " + std::to_string(i) + "- or " +
                                      std::to_string(i + 1) + "-G-maps, not of a " + std::to_string(n) + "-G-map",
                p.name);
  Dart t0 = kNoDart;
  for (Dart d : f)
    if (d != kNoDart) {
      t0 = d;
      break;
    }
  if (t0 == kNoDart) throw Error(ErrorCode::Usage, "empty match", p.name);
  const bool shared = n > i && !g.is_free(i + 1, t0);
  std::vector<Dart> copy(q.capacity(), kNoDart), mirror;
  if (shared) mirror.assign(q.capacity(), kNoDart);
  q.for_each_dart([&](Dart x) {
    if (q.is_free(i, x)) return;
    copy[x] = g.add_dart();
    if (shared) mirror[x] = g.add_dart();
  });
  target.resize_flags();
  q.for_each_dart([&](Dart x) {
    if (copy[x] == kNoDart) return;
    for (int j = 0; j <= i; ++j) {
      const Dart y = q.alpha(j, x);
      if (copy[y] != kNoDart) {
        g.link(j, copy[x], copy[y]);
        if (shared) g.link(j, mirror[x], mirror[y]);
      } else {  // j == i - 1 and y on the boundary: the only relinked dimension
        g.link(j, copy[x], f[y]);
        if (shared) g.link(j, mirror[x], g.alpha(i + 1, f[y]));
      }
    }
    if (shared) g.link(i + 1, copy[x], mirror[x]);
    target.flag[copy[x]] = x < p.map.flag.size() ? p.map.flag[x] : 0;
    if (shared) target.flag[mirror[x]] = target.flag[copy[x]];
  });
  if (target.positioned()) place_interior(target, p, f, copy, mirror);
  return p.interior * (shared ? 2 : 1);
}

}  // namespace gmr::replace
