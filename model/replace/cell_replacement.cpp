#include "model/replace/cell_replacement.hpp"

#include "model/core/error.hpp"
#include "model/core/orbit.hpp"
#include "model/core/position.hpp"

namespace gmr::replace {

namespace {

// §5.2: a copied dart at a boundary vertex takes the target's position of that vertex; at an
// interior vertex, the pattern's mean value coordinates applied to the target's boundary positions
// (the origin when the pattern has no geometry). `mirror` is the offset of the mirror copies (0:
// none).
void place_interior(FlaggedMap& target, const Pattern& p, const std::vector<Dart>& f, const std::vector<Dart>& copy,
                    size_t mirror) {
  thread_local std::vector<Vec3> at;
  at.assign(p.vertex_anchor.size(), Vec3{0, 0, 0});
  for (size_t v = 0; v < p.vertex_anchor.size(); ++v)
    if (p.vertex_anchor[v] != kNoDart) at[v] = target.position[f[p.vertex_anchor[v]]];
  for (const InteriorVertex& v : p.interior_vertices) {
    Vec3 x{0, 0, 0};
    for (const auto& [b, w] : v.weights)
      for (int c = 0; c < 3; ++c) x[c] += w * target.position[f[b]][c];
    at[p.vertex_of[v.dart]] = x;
  }
  for (Dart x : p.interior_darts) {
    const Vec3& y = at[p.vertex_of[x]];
    target.position[copy[x]] = y;
    if (mirror) target.position[copy[x] + mirror] = y;
  }
}

}  // namespace

size_t replace_cell(FlaggedMap& target, const Pattern& p, const std::vector<Dart>& f) {
  Map& g = target.map;
  const Map& q = p.map.map;
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
  // The copies are new consecutive darts: copy[x] for the interior dart x, and its mirror copy
  // (the other half-face) at copy[x] + k.
  const size_t k = p.interior_darts.size();
  const Dart first = g.add_darts(k * (shared ? 2 : 1));
  const Dart mirror = shared ? static_cast<Dart>(k) : 0;
  thread_local std::vector<Dart> copy;
  copy.assign(q.capacity(), kNoDart);
  for (size_t j = 0; j < k; ++j) copy[p.interior_darts[j]] = first + static_cast<Dart>(j);
  target.resize_flags();
  for (Dart x : p.interior_darts) {
    for (int j = 0; j <= i; ++j) {
      const Dart y = q.alpha(j, x);
      if (copy[y] != kNoDart) {  // both copies are written from both sides: one direction each
        g.set_alpha(j, copy[x], copy[y]);
        if (shared) g.set_alpha(j, copy[x] + mirror, copy[y] + mirror);
      } else {  // j == i - 1 and y on the boundary: the only relinked dimension
        g.link(j, copy[x], f[y]);
        if (shared) g.link(j, copy[x] + mirror, g.alpha(i + 1, f[y]));
      }
    }
    if (shared) g.link(i + 1, copy[x], copy[x] + mirror);
    target.flag[copy[x]] = x < p.map.flag.size() ? p.map.flag[x] : 0;
    if (shared) target.flag[copy[x] + mirror] = target.flag[copy[x]];
  }
  if (target.positioned()) place_interior(target, p, f, copy, mirror);
  return p.interior * (shared ? 2 : 1);
}

}  // namespace gmr::replace
