#include "model/replace/replacement_template.hpp"

#include "model/core/error.hpp"

namespace gmr::replace {

ReplacementTemplate compile_replacement(const Pattern& p, const std::vector<uint32_t>& order) {
  const Map& q = p.map.map;
  const int i = p.cell_dim;
  ReplacementTemplate t;
  t.cell_dim = i;
  t.interior = static_cast<uint32_t>(p.interior_darts.size());
  t.boundary = static_cast<uint32_t>(order.size());
  const uint32_t k = t.interior;
  // Pattern dart -> its number: interior index, or k + its rank in label order on the boundary.
  std::vector<uint32_t> index(q.capacity(), UINT32_MAX);
  for (uint32_t j = 0; j < k; ++j) index[p.interior_darts[j]] = j;
  for (uint32_t b = 0; b < t.boundary; ++b) index[p.boundary.dart[order[b]]] = k + b;
  t.link.reserve(size_t(k) * (i + 1));
  t.flag.reserve(k);
  t.vertex.reserve(k);
  // Interior vertices (no boundary dart), numbered on first use; their weights from the pattern's
  // mean value coordinates, if any.
  std::vector<uint32_t> interior_vertex(p.vertex_anchor.size(), UINT32_MAX);
  for (Dart x : p.interior_darts) {
    for (int d = 0; d <= i; ++d) {
      const uint32_t y = index[q.alpha(d, x)];
      // Only alpha_{i-1} leaves the interior: alpha_j alpha_i is an involution for j <= i - 2,
      // so an interior dart's alpha_j (j != i - 1) is not i-free.
      if (y == UINT32_MAX || (y >= k && d != i - 1))
        throw Error(ErrorCode::Schema, "interior dart " + std::to_string(x) + " is " + std::to_string(d) +
                                           "-linked outside the interior and boundary", p.name);
      t.link.push_back(y);
    }
    t.flag.push_back(x < p.map.flag.size() ? p.map.flag[x] : 0);
    const uint32_t v = p.vertex_of[x];
    const Dart anchor = p.vertex_anchor[v];
    if (anchor != kNoDart) {
      t.vertex.push_back(ReplacementTemplate::kOnBoundary | (index[anchor] - k));
      continue;
    }
    if (interior_vertex[v] == UINT32_MAX) {
      interior_vertex[v] = static_cast<uint32_t>(t.weights.size());
      t.weights.emplace_back();
      for (const InteriorVertex& iv : p.interior_vertices)
        if (p.vertex_of[iv.dart] == v)
          for (const auto& [b, w] : iv.weights) t.weights.back().emplace_back(index[b] - k, w);
    }
    t.vertex.push_back(interior_vertex[v]);
  }
  return t;
}

}  // namespace gmr::replace
