#include "model/replace/unit_hex_positions.hpp"

#include <array>

#include "model/core/error.hpp"

namespace gmr::replace {

std::vector<Vec3> unit_hex_positions(const Map& g, double length) {
  if (g.is_omap() || g.dimension() != 3)
    throw Error(ErrorCode::InvalidMap, "unit hexahedra are laid out in 3-G-maps");
  using Frame = std::array<Vec3, 3>;
  std::vector<Vec3> pos(g.capacity(), Vec3{0, 0, 0});
  std::vector<Frame> frame(g.capacity());
  std::vector<uint8_t> seen(g.capacity(), 0);
  std::vector<Dart> queue;
  g.for_each_dart([&](Dart d) {
    if (!queue.empty()) return;
    queue.push_back(d);
    seen[d] = 1;
    frame[d] = {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
  });
  auto neg = [](const Vec3& v) { return Vec3{-v[0], -v[1], -v[2]}; };
  for (size_t k = 0; k < queue.size(); ++k) {
    const Dart x = queue[k];
    const Frame& f = frame[x];
    for (int i = 0; i <= 3; ++i) {
      const Dart y = g.alpha(i, x);
      Vec3 p = pos[x];
      Frame h = f;
      if (i == 0) {
        for (int c = 0; c < 3; ++c) p[c] += length * f[0][c];
        h[0] = neg(f[0]);
      } else if (i == 1) {
        std::swap(h[0], h[1]);
      } else if (i == 2) {
        std::swap(h[1], h[2]);
      } else {
        h[2] = neg(f[2]);
      }
      if (!seen[y]) {
        seen[y] = 1;
        pos[y] = p;
        frame[y] = h;
        queue.push_back(y);
      } else if (pos[y] != p) {
        throw Error(ErrorCode::InvalidMap, "not a mesh of unit cubes", "dart " + std::to_string(y));
      }
    }
  }
  if (queue.size() != g.size())
    throw Error(ErrorCode::InvalidMap, "unit hexahedra: the map is not connected");
  return pos;
}

}  // namespace gmr::replace
