#include "model/replace/edge_split.hpp"

#include <unordered_map>

#include "model/core/error.hpp"
#include "model/core/orbit.hpp"

namespace gmr::replace {

size_t split_edge(FlaggedMap& m, Dart d, unsigned k) {
  if (k == 0) throw Error(ErrorCode::Usage, "an edge is split into at least 1 edge");
  if (k == 1) return 0;
  Map& g = m.map;
  const std::vector<Dart> edge = orbit(g, cell_type(g, 1), d);
  const Dart len = 2 * (k - 1);
  // chain of x: first new dart and direction (+1 from x's side, -1 from the other end).
  std::unordered_map<Dart, std::pair<Dart, int>> chain;
  for (Dart x : edge) {
    const Dart y = g.alpha(0, x);
    if (y == x) throw Error(ErrorCode::InvalidMap, "a 0-free dart has no edge to split", "dart " + std::to_string(x));
    if (chain.count(x)) continue;
    const Dart first = g.add_darts(len);
    chain[x] = {first, +1};
    chain[y] = {static_cast<Dart>(first + len - 1), -1};
    g.link(0, x, first);
    for (Dart s = 0; s + 1 < len; ++s) g.link(s % 2 == 0 ? 1 : 0, first + s, first + s + 1);
    g.link(0, first + len - 1, y);
    if (m.positioned()) {  // vertex t (1..k-1) at t/k from x's vertex
      m.position.resize(g.capacity(), Vec3{0, 0, 0});
      const Vec3 a = m.position[x], b = m.position[y];
      for (Dart s = 0; s < len; ++s) {
        const double t = double(s / 2 + 1) / k;
        m.position[first + s] = {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
      }
    }
  }
  for (Dart x : edge) {
    const auto [fx, dx] = chain.at(x);
    for (int j = 2; j <= g.dimension(); ++j) {
      const Dart z = g.alpha(j, x);
      if (z == x) continue;
      const auto [fz, dz] = chain.at(z);
      for (Dart s = 0; s < len; ++s) g.link(j, dx > 0 ? fx + s : fx - s, dz > 0 ? fz + s : fz - s);
    }
  }
  m.resize_flags();
  return edge.size() * (k - 1);
}

}  // namespace gmr::replace
