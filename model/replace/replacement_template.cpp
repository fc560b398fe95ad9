#include "model/replace/replacement_template.hpp"

#include <algorithm>

#include "model/core/error.hpp"

namespace gmr::replace {

namespace {

// Per boundary rank (label order `order`), the first rank of its vertex: the orbit of neighbours
// 1..m of the boundary graph (arity m + 1).
std::vector<uint32_t> boundary_vertex_ranks(const BoundaryGraph& b,
                                            const std::vector<uint32_t>& order) {
  std::vector<uint32_t> rank_of(b.size()), out(order.size(), UINT32_MAX), stack;
  for (uint32_t r = 0; r < order.size(); ++r) rank_of[order[r]] = r;
  for (uint32_t r = 0; r < order.size(); ++r) {
    if (out[r] != UINT32_MAX) continue;
    out[r] = r;
    stack.assign(1, order[r]);
    while (!stack.empty()) {
      const uint32_t x = stack.back();
      stack.pop_back();
      for (int j = 1; j < b.arity; ++j) {
        const uint32_t y = b.neighbour(x, j);
        if (out[rank_of[y]] == UINT32_MAX) {
          out[rank_of[y]] = r;
          stack.push_back(y);
        }
      }
    }
  }
  return out;
}

}  // namespace

ReplacementTemplate compile_replacement(const Pattern& p, uint32_t start) {
  const Map& q = p.map.map;
  const int i = p.cell_dim;
  const std::vector<uint32_t> order = boundary_labeling(p.boundary, start);
  ReplacementTemplate t;
  t.cell_dim = i;
  t.interior = static_cast<uint32_t>(p.interior_darts.size());
  t.boundary = static_cast<uint32_t>(order.size());
  t.word = boundary_word(p.boundary, start);
  const uint32_t k = t.interior;
  // Pattern dart -> its number: interior index, or k + its rank in label order on the boundary.
  std::vector<uint32_t> index(q.capacity(), UINT32_MAX);
  for (uint32_t j = 0; j < k; ++j) index[p.interior_darts[j]] = j;
  for (uint32_t b = 0; b < t.boundary; ++b) index[p.boundary.dart[order[b]]] = k + b;
  for (int d = 0; d <= i; ++d) t.link[d].reserve(k);
  t.flag.reserve(k);
  // Interior vertices (no boundary dart), numbered on first use; their weights from the pattern's
  // mean value coordinates, if any.
  std::vector<uint32_t> interior_vertex(p.vertex_anchor.size(), UINT32_MAX);
  std::vector<double> vertex_weight(t.boundary, 0.0);
  // The boundary's vertices: the orbits of the boundary graph's neighbours 1..m (alpha_1 and
  // the boundary successor, or alpha_1 and abar_2), mapped by f into one vertex of the target, each
  // named by its first dart in label order. Every dart of a vertex has its position, so a copied
  // dart at a boundary vertex, and a mean value weight, read it there: each boundary vertex is read
  // at one place.
  const std::vector<uint32_t> vertex_rank = boundary_vertex_ranks(p.boundary, order);
  for (uint32_t j = 0; j < k; ++j) {
    const Dart x = p.interior_darts[j];
    for (int d = 0; d <= i; ++d) {
      const uint32_t y = index[q.alpha(d, x)];
      // Only alpha_{i-1} leaves the interior: alpha_j alpha_i is an involution for j <= i - 2,
      // so an interior dart's alpha_j (j != i - 1) is not i-free.
      if (y == UINT32_MAX || (y >= k && d != i - 1))
        throw Error(ErrorCode::Schema,
                    "interior dart " + std::to_string(x) + " is " + std::to_string(d) +
                        "-linked outside the interior and boundary",
                    p.name);
      t.link[d].push_back(y < k ? y : j);
      if (y >= k) t.relinks.emplace_back(j, y - k);
      if (d == i - 1) t.relink_rank.push_back(y < k ? ReplacementTemplate::kInterior : y - k);
    }
    t.flag.push_back(x < p.map.flag.size() ? p.map.flag[x] : 0);
    const uint32_t v = p.vertex_of[x];
    const Dart anchor = p.vertex_anchor[v];
    if (anchor != kNoDart) {
      t.at_boundary_vertex.emplace_back(j, vertex_rank[index[anchor] - k]);
      t.vertex_source.push_back(vertex_rank[index[anchor] - k]);
      continue;
    }
    if (interior_vertex[v] == UINT32_MAX) {
      interior_vertex[v] = static_cast<uint32_t>(t.weights.size());
      t.weights.emplace_back();
      // One weight per boundary vertex (the mean value coordinates of a v-pattern give one per
      // corner of each triangle of the fan-triangulated boundary), on its first dart.
      for (const InteriorVertex& iv : p.interior_vertices)
        if (p.vertex_of[iv.dart] == v)
          for (const auto& [b, w] : iv.weights) vertex_weight[vertex_rank[index[b] - k]] += w;
      for (uint32_t b = 0; b < t.boundary; ++b)
        if (vertex_weight[b] != 0) {
          t.weights.back().emplace_back(b, vertex_weight[b]);
          vertex_weight[b] = 0;
        }
    }
    t.at_interior_vertex.emplace_back(j, interior_vertex[v]);
    t.vertex_source.push_back(t.boundary + interior_vertex[v]);
  }
  for (const auto& [j, b] : t.at_boundary_vertex) t.vertex_reads.push_back(b);
  for (const auto& w : t.weights)
    for (const auto& [b, x] : w) t.vertex_reads.push_back(b);
  std::sort(t.vertex_reads.begin(), t.vertex_reads.end());
  t.vertex_reads.erase(std::unique(t.vertex_reads.begin(), t.vertex_reads.end()),
                       t.vertex_reads.end());
  return t;
}

}  // namespace gmr::replace
