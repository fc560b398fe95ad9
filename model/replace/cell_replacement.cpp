#include "model/replace/cell_replacement.hpp"

namespace gmr::replace {

namespace {

// §5.2: a copied dart at a boundary vertex takes the target's position of that vertex; at an
// interior vertex, the pattern's mean value coordinates applied to the target's boundary positions
// (the origin when the pattern has no geometry). `mirror` is the offset of the mirror copies (0:
// none).
void place_interior(FlaggedMap& target, const ReplacementTemplate& t, const Dart* f, Dart first, Dart mirror) {
  thread_local std::vector<Vec3> at;
  at.resize(t.weights.size());
  Vec3* pos = target.position.data();
  for (size_t v = 0; v < t.weights.size(); ++v) {
    Vec3 x{0, 0, 0};
    for (const auto& [b, w] : t.weights[v])
      for (int c = 0; c < 3; ++c) x[c] += w * pos[f[b]][c];
    at[v] = x;
  }
  for (const auto& [j, b] : t.at_boundary_vertex) pos[first + j] = pos[f[b]];
  for (const auto& [j, v] : t.at_interior_vertex) pos[first + j] = at[v];
  if (mirror) std::copy(pos + first, pos + first + t.interior, pos + first + mirror);
}

// One link array of the copies: interior dart j's neighbour y becomes first + y.
void copy_links(Map& g, int d, const std::vector<uint32_t>& link, Dart first) {
  Dart* __restrict out = g.link_data(d) + first;
  const uint32_t* __restrict in = link.data();
  const uint32_t k = static_cast<uint32_t>(link.size());
  for (uint32_t j = 0; j < k; ++j) out[j] = first + in[j];
}

}  // namespace

size_t replace_cell(FlaggedMap& target, const ReplacementTemplate& t, const Dart* f, Dart first, bool shared) {
  Map& g = target.map;
  const int i = t.cell_dim;
  const uint32_t k = t.interior;
  // The copy of interior dart j is first + j, its mirror copy (the other half-face) first + j + k.
  // 1. Each link array written once, in dart order, as the pattern links its interior.
  for (int d = 0; d <= i; ++d) {
    copy_links(g, d, t.link[d], first);
    if (shared) copy_links(g, d, t.link[d], first + k);
  }
  if (shared) {
    Dart* __restrict out = g.link_data(i + 1) + first;
    for (uint32_t j = 0; j < k; ++j) {
      out[j] = first + k + j;
      out[k + j] = first + j;
    }
  }
  // 2. The relinks of alpha_{i-1}: the only links between the copies and the cell's boundary.
  for (const auto& [j, b] : t.relinks) {
    const Dart x = first + j, y = f[b];
    g.set_alpha(i - 1, x, y);
    g.set_alpha(i - 1, y, x);
    if (shared) {
      const Dart y3 = g.alpha(i + 1, y);
      g.set_alpha(i - 1, x + k, y3);
      g.set_alpha(i - 1, y3, x + k);
    }
  }
  std::copy(t.flag.begin(), t.flag.end(), target.flag.begin() + first);
  if (shared) std::copy(t.flag.begin(), t.flag.end(), target.flag.begin() + first + k);
  if (target.positioned()) place_interior(target, t, f, first, shared ? k : 0);
  return size_t(k) * (shared ? 2 : 1);
}

size_t replace_cell(FlaggedMap& target, const ReplacementTemplate& t, const Dart* f, bool shared) {
  const Dart first = target.map.add_darts(size_t(t.interior) * (shared ? 2 : 1));
  target.resize_flags();
  return replace_cell(target, t, f, first, shared);
}

}  // namespace gmr::replace
