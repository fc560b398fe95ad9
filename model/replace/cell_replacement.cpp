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
  std::vector<Vec3>& pos = target.position;
  // The boundary positions are scattered in the target: all fetched before the sums read them.
  for (const auto& ws : t.weights)
    for (const auto& bw : ws) __builtin_prefetch(&pos[f[bw.first]]);
  for (size_t v = 0; v < t.weights.size(); ++v) {
    Vec3 x{0, 0, 0};
    for (const auto& [b, w] : t.weights[v])
      for (int c = 0; c < 3; ++c) x[c] += w * pos[f[b]][c];
    at[v] = x;
  }
  for (uint32_t j = 0; j < t.interior; ++j) {
    const uint32_t v = t.vertex[j];
    const Vec3 y = v & ReplacementTemplate::kOnBoundary ? pos[f[v & ~ReplacementTemplate::kOnBoundary]] : at[v];
    pos[first + j] = y;
    if (mirror) pos[first + j + mirror] = y;
  }
}

}  // namespace

size_t replace_cell(FlaggedMap& target, const ReplacementTemplate& t, const Dart* f, Dart first, bool shared) {
  Map& g = target.map;
  const int i = t.cell_dim;
  const uint32_t k = t.interior;
  // The copy of interior dart j is first + j, its mirror copy (the other half-face) first + j + k.
  const Dart mirror = shared ? k : 0;
  const uint32_t* link = t.link.data();
  for (uint32_t j = 0; j < k; ++j) {
    const Dart x = first + j;
    for (int d = 0; d <= i; ++d) {
      const uint32_t y = *link++;
      if (y < k) {  // both copies are written from both sides: one direction each
        g.set_alpha(d, x, first + y);
        if (shared) g.set_alpha(d, x + mirror, first + y + mirror);
      } else {  // d == i - 1 and y on the boundary: the only relinked dimension
        const Dart b = f[y - k];
        g.set_alpha(d, x, b);
        g.set_alpha(d, b, x);
        if (shared) {
          const Dart b3 = g.alpha(i + 1, b);
          g.set_alpha(d, x + mirror, b3);
          g.set_alpha(d, b3, x + mirror);
        }
      }
    }
    target.flag[x] = t.flag[j];
    if (shared) {
      g.set_alpha(i + 1, x, x + mirror);
      g.set_alpha(i + 1, x + mirror, x);
      target.flag[x + mirror] = t.flag[j];
    }
  }
  if (target.positioned()) place_interior(target, t, f, first, mirror);
  return size_t(k) * (shared ? 2 : 1);
}

}  // namespace gmr::replace
