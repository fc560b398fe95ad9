#include "model/replace/interior_geometry.hpp"

#include <cmath>

#include "model/core/orbit.hpp"
#include "model/core/position.hpp"
#include "model/replace/boundary_graph.hpp"

namespace gmr::replace {

namespace {

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }

// The boundary faces of the pattern as cycles of boundary darts, one dart per corner (f-pattern:
// one polygon along alpha_0 and the boundary successor; v-pattern: the <0,1>-orbits of 3-free
// darts).
std::vector<std::vector<Dart>> boundary_polygons(const Map& p,
                                                 const std::vector<uint8_t>& positive) {
  const int n = p.dimension();
  std::vector<std::vector<Dart>> polys;
  std::vector<uint8_t> seen(p.capacity(), 0);
  p.for_each_dart([&](Dart d) {
    if (!p.is_free(n, d) || seen[d] || (n == 3 && !positive[d])) return;
    std::vector<Dart> poly;
    Dart x = d;
    do {  // x and alpha_0(x) are the two ends of a boundary edge; step to the next corner
      poly.push_back(x);
      seen[x] = 1;
      const Dart y = p.alpha(0, x);
      seen[y] = 1;
      x = n == 2 ? boundary_successor(p, 1, y) : p.alpha(1, y);
    } while (x != d && !seen[x]);
    polys.push_back(std::move(poly));
  });
  return polys;
}

}  // namespace

std::vector<InteriorVertex> mean_value_coordinates(const Map& p, const std::vector<Vec3>& pos,
                                                   const std::vector<uint8_t>& positive) {
  const int n = p.dimension();
  const auto polys = boundary_polygons(p, positive);
  std::vector<InteriorVertex> out;
  const OrbitType vertex = vertex_orbit_type(p);
  for (Dart rep : orbit_representatives(p, vertex)) {
    bool boundary = false;
    for (Dart x : orbit(p, vertex, rep)) boundary |= p.is_free(n, x);
    if (boundary) continue;
    InteriorVertex v;
    v.dart = rep;
    const Vec3 x = pos[rep];
    double total = 0;
    auto add = [&](Dart d, double w) {
      v.weights.emplace_back(d, w);
      total += w;
    };
    if (n == 2) {  // Floater's mean value coordinates of the boundary polygon (unsigned angles:
                   // exact when x sees the whole boundary, docs/query-replace.md)
      const auto& poly = polys.front();
      const size_t k = poly.size();
      std::vector<double> tan_half(k), len(k);
      for (size_t j = 0; j < k; ++j) {
        const Vec3 a = sub(pos[poly[j]], x), b = sub(pos[poly[(j + 1) % k]], x);
        len[j] = norm(a);
        tan_half[j] = norm(cross(a, b)) / (norm(a) * norm(b) + dot(a, b));
      }
      for (size_t j = 0; j < k; ++j)
        add(poly[j], (tan_half[(j + k - 1) % k] + tan_half[j]) / len[j]);
    } else {  // Ju, Schaefer & Warren: closed triangle mesh (polygons fan-triangulated)
      for (const auto& poly : polys)
        for (size_t t = 1; t + 1 < poly.size(); ++t) {
          const Dart tri[3] = {poly[0], poly[t], poly[t + 1]};
          Vec3 u[3];
          double d[3];
          for (int i = 0; i < 3; ++i) {
            const Vec3 r = sub(pos[tri[i]], x);
            d[i] = norm(r);
            u[i] = {r[0] / d[i], r[1] / d[i], r[2] / d[i]};
          }
          double theta[3], c[3], s[3];
          for (int i = 0; i < 3; ++i)
            theta[i] = 2 * std::asin(std::min(1.0, norm(sub(u[(i + 1) % 3], u[(i + 2) % 3])) / 2));
          const double h = (theta[0] + theta[1] + theta[2]) / 2;
          const double sign = dot(cross(u[0], u[1]), u[2]) < 0 ? -1.0 : 1.0;
          bool skip = false;
          for (int i = 0; i < 3; ++i) {
            c[i] = 2 * std::sin(h) * std::sin(h - theta[i]) /
                       (std::sin(theta[(i + 1) % 3]) * std::sin(theta[(i + 2) % 3])) -
                   1;
            s[i] = sign * std::sqrt(std::max(0.0, 1 - c[i] * c[i]));
            skip |= std::abs(s[i]) <= 1e-12;
          }
          if (skip) continue;  // x in the triangle's plane, outside it: no contribution
          for (int i = 0; i < 3; ++i) {
            const int a = (i + 1) % 3, b = (i + 2) % 3;
            add(tri[i], (theta[i] - c[a] * theta[b] - c[b] * theta[a]) /
                            (d[i] * std::sin(theta[a]) * s[b]));
          }
        }
    }
    for (auto& [dart, w] : v.weights) w /= total;
    out.push_back(std::move(v));
  }
  return out;
}

}  // namespace gmr::replace
