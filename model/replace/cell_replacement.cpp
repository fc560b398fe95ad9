#include "model/replace/cell_replacement.hpp"

#include <algorithm>

#include "model/core/generated_append.hpp"

namespace gmr::replace {

namespace {

// §5.2: a copied dart at a boundary vertex takes the target's position of that vertex; at an
// interior vertex, the pattern's mean value coordinates applied to the target's boundary positions
// (the origin when the pattern has no geometry). `mirror` is the offset of the mirror copies (0:
// none).
void place_interior(FlaggedMap& target, const ReplacementTemplate& t, const Dart* f, Dart first,
                    Dart mirror) {
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

// place_interior for new darts appended at the end (the positions written once, in dart order).
// The boundary positions read were prefetched (prefetch_boundary_positions).
void append_interior_positions(FlaggedMap& target, const ReplacementTemplate& t, const Dart* f,
                               bool shared) {
  thread_local std::vector<Vec3> at;
  std::vector<Vec3>& pos = target.position;
  const uint32_t boundary = t.boundary;
  // The interior vertices, then every copy's position: boundary ones read where they are.
  at.resize(t.weights.size());
  for (size_t v = 0; v < t.weights.size(); ++v) {
    Vec3 x{0, 0, 0};
    for (const auto& [b, w] : t.weights[v])
      for (int c = 0; c < 3; ++c) x[c] += w * pos[f[b]][c];
    at[v] = x;
  }
  const Vec3* p = pos.data();
  const Vec3* inner = at.data();
  const uint32_t* src = t.vertex_source.data();
  // Both sources addressed and one selected (no branch on the template's per-dart pattern).
  auto position = [&](size_t j) {
    const uint32_t s = src[j];
    const bool at_boundary = s < boundary;
    const Vec3* from_boundary = p + f[at_boundary ? s : 0];
    const Vec3* from_inner = inner + (at_boundary ? 0 : s - boundary);
    return *(at_boundary ? from_boundary : from_inner);
  };
  p = pos.data();  // stays valid below: replace_cell grew the positions for the copies
  const size_t base = pos.size();
  append_generated(pos, t.interior, position);
  if (shared) append_generated(pos, t.interior, [&](size_t j) { return p[base + j]; });
}

// One link array of the copies: interior dart j's neighbour y becomes first + y.
void copy_links(Map& g, int d, const std::vector<uint32_t>& link, Dart first) {
  Dart* __restrict out = g.link_data(d) + first;
  const uint32_t* __restrict in = link.data();
  const uint32_t k = static_cast<uint32_t>(link.size());
  for (uint32_t j = 0; j < k; ++j) out[j] = first + in[j];
}

}  // namespace

size_t replace_cell(FlaggedMap& target, const ReplacementTemplate& t, const Dart* f, Dart first,
                    bool shared) {
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
  // The same writes, appended: each link array, the flags and the positions of the new darts are
  // written once, in dart order, with no free (or zero) state first (Map::add_linked_darts).
  Map& g = target.map;
  if (target.flag.size() != g.capacity() ||
      (target.positioned() && target.position.size() != g.capacity()))
    target.resize_flags();
  const int i = t.cell_dim;
  const uint32_t k = t.interior;
  // The boundary positions read below are scattered (four generations of darts): fetched while
  // the links are written.
  if (target.positioned())
    for (uint32_t b : t.vertex_reads) __builtin_prefetch(target.position.data() + f[b]);
  // 1. The links: the copy of interior dart j is first + j, its mirror copy first + k + j; the
  // alpha_{i-1} of a dart at the boundary is f of the boundary dart (and its alpha_{i+1} for the
  // mirror copy).
  const Dart first =
      g.add_linked_darts(size_t(k) * (shared ? 2 : 1), [&](int d, Dart from, LinkAppender& out) {
        if (d > i) {  // alpha_{i+1} (d = i + 1): the two half-cells sewn copy by copy, or free
          if (shared) {
            out.append(k, [&](size_t j) { return from + k + static_cast<Dart>(j); });
            out.append(k, [&](size_t j) { return from + static_cast<Dart>(j); });
          } else {
            out.append(k, [&](size_t j) { return from + static_cast<Dart>(j); });
          }
          return;
        }
        const uint32_t* link = t.link[d].data();
        if (d != i - 1) {
          for (Dart base = from, h = 0; h < (shared ? 2u : 1u); ++h, base += k)
            out.append(k, [&](size_t j) { return base + link[j]; });
          return;
        }
        const uint32_t* rank = t.relink_rank.data();
        // alpha_{i+1} read where it is now (the arrays may have moved as they grew; it is appended
        // after this dimension).
        const Dart* across = shared ? g.links(i + 1).data() : nullptr;
        // Both links read and one selected (no branch on the template's per-dart pattern).
        out.append(k, [&](size_t j) {
          const uint32_t b = rank[j];
          const bool inside = b == ReplacementTemplate::kInterior;
          const Dart boundary_dart = f[inside ? 0 : b];
          return inside ? from + link[j] : boundary_dart;
        });
        if (shared)
          out.append(k, [&](size_t j) {
            const uint32_t b = rank[j];
            const bool inside = b == ReplacementTemplate::kInterior;
            const Dart boundary_dart = across[f[inside ? 0 : b]];
            return inside ? from + k + link[j] : boundary_dart;
          });
      });
  // 2. The boundary's side of the relinks.
  for (const auto& [j, b] : t.relinks) {
    const Dart y = f[b];
    if (shared) g.set_alpha(i - 1, g.alpha(i + 1, y), first + k + j);
    g.set_alpha(i - 1, y, first + j);
  }
  // 3. Flags and positions, appended.
  target.grow_flags(g.capacity());
  for (int h = 0; h < (shared ? 2 : 1); ++h)
    target.flag.insert(target.flag.end(), t.flag.begin(), t.flag.end());
  if (target.positioned()) append_interior_positions(target, t, f, shared);
  return size_t(k) * (shared ? 2 : 1);
}

}  // namespace gmr::replace
