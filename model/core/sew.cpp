#include "model/core/sew.hpp"

#include <unordered_map>

#include "model/core/error.hpp"
#include "model/core/orbit.hpp"

namespace gmr {

OrbitType sew_orbit_type(const Map& g, int i) {
  std::vector<int> dims;
  for (int k = 0; k <= g.dimension(); ++k)
    if (k < i - 1 || k > i + 1) dims.push_back(k);
  return OrbitType(std::move(dims));
}

static void require_gmap_dim(const Map& g, int i) {
  if (g.is_omap())
    throw Error(ErrorCode::Usage, "sewing is implemented for G-maps only (O-map sew: not yet)");
  if (!g.has_dim(i))
    throw Error(ErrorCode::Range, "sew dimension " + std::to_string(i) + " outside 0.." +
                                      std::to_string(g.dimension()));
}

bool is_sewable(const Map& g, int i, Dart d1, Dart d2, std::string* why) {
  require_gmap_dim(g, i);
  auto fail = [&](std::string s) {
    if (why) *why = std::move(s);
    return false;
  };
  if (!g.alive(d1) || !g.alive(d2)) return fail("no such dart");
  if (d1 == d2) return fail("a dart cannot be sewn to itself (it is already an i-loop)");
  const OrbitType o = sew_orbit_type(g, i);
  auto pairs = orbit_isomorphism(g, o, d1, g, o, d2);
  if (!pairs)
    return fail("the " + o.str() + "-orbits of darts " + std::to_string(d1) + " and " +
                std::to_string(d2) + " are not isomorphic");
  for (auto [x, y] : *pairs) {
    if (!g.is_free(i, x))
      return fail("dart " + std::to_string(x) + " is not " + std::to_string(i) + "-free");
    if (!g.is_free(i, y))
      return fail("dart " + std::to_string(y) + " is not " + std::to_string(i) + "-free");
  }
  // Overlapping orbits (sewing an orbit onto itself): each dart must get one partner, symmetric.
  std::unordered_map<Dart, Dart> to;
  for (auto [x, y] : *pairs) {
    auto check = [&](Dart a, Dart b) {
      auto [it, fresh] = to.emplace(a, b);
      return fresh || it->second == b;
    };
    if (!check(x, y) || !check(y, x))
      return fail("dart " + std::to_string(x) + " would get two " + std::to_string(i) +
                  "-partners");
  }
  return true;
}

void sew(Map& g, int i, Dart d1, Dart d2) {
  std::string why;
  if (!is_sewable(g, i, d1, d2, &why))
    throw Error(ErrorCode::Sew, std::to_string(i) + "-sew refused: " + why,
                "darts " + std::to_string(d1) + ", " + std::to_string(d2));
  const OrbitType o = sew_orbit_type(g, i);
  const auto pairs = orbit_isomorphism(g, o, d1, g, o, d2);
  for (auto [x, y] : *pairs) g.link(i, x, y);
}

void unsew(Map& g, int i, Dart d) {
  require_gmap_dim(g, i);
  if (!g.alive(d)) throw Error(ErrorCode::Sew, "no such dart", "dart " + std::to_string(d));
  if (g.is_free(i, d))
    throw Error(
        ErrorCode::Sew,
        std::to_string(i) + "-unsew refused: dart is already " + std::to_string(i) + "-free",
        "dart " + std::to_string(d));
  for (Dart x : orbit(g, sew_orbit_type(g, i), d)) g.unlink(i, x);
}

}  // namespace gmr
