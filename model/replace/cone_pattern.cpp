#include "model/replace/cone_pattern.hpp"

#include <unordered_set>

#include "model/core/error.hpp"
#include "model/core/orbit.hpp"
#include "model/core/validity.hpp"
#include "model/replace/configurations.hpp"
#include "model/replace/orientation.hpp"
#include "model/replace/pattern_store.hpp"

namespace gmr::replace {

FlaggedMap cone_of_surface(const FlaggedMap& surface) {
  const Map& s = surface.map;
  if (s.is_omap() || s.dimension() != 2)
    throw Error(ErrorCode::InvalidMap, "a cone is built on a 2-G-map surface");
  if (s.has_holes()) throw Error(ErrorCode::InvalidMap, "the surface has deleted darts");
  const ValidityReport v = check_validity(s, 1);
  if (!v.ok())
    throw Error(ErrorCode::InvalidMap,
                "the surface is not valid: " + to_text(v.violations.front()));
  s.for_each_dart([&](Dart d) {
    for (int i = 0; i <= 2; ++i)
      if (s.is_free(i, d))
        throw Error(ErrorCode::InvalidMap,
                    "the surface is not closed (an " + std::to_string(i) + "-free dart)",
                    "dart " + std::to_string(d));
  });
  const Dart n = s.capacity();
  FlaggedMap c{Map(3), {}, {}};
  Map& g = c.map;
  g.add_darts(size_t(4) * n);
  // b(d) = d, t0(d) = n + d, t1(d) = 2n + d, t2(d) = 3n + d.
  auto b = [](Dart d) { return d; };
  auto t0 = [n](Dart d) { return n + d; };
  auto t1 = [n](Dart d) { return 2 * n + d; };
  auto t2 = [n](Dart d) { return 3 * n + d; };
  for (Dart d = 0; d < n; ++d) {
    const Dart a0 = s.alpha(0, d), a1 = s.alpha(1, d), a2 = s.alpha(2, d);
    g.set_alpha(0, b(d), b(a0));
    g.set_alpha(1, b(d), b(a1));
    g.set_alpha(2, b(d), t0(d));
    g.set_alpha(0, t0(d), t0(a0));
    g.set_alpha(1, t0(d), t1(d));
    g.set_alpha(2, t0(d), b(d));
    g.set_alpha(3, t0(d), t0(a2));
    g.set_alpha(0, t1(d), t2(d));
    g.set_alpha(1, t1(d), t0(d));
    g.set_alpha(2, t1(d), t1(a1));
    g.set_alpha(3, t1(d), t1(a2));
    g.set_alpha(0, t2(d), t1(d));
    g.set_alpha(1, t2(d), t2(a0));
    g.set_alpha(2, t2(d), t2(a1));
    g.set_alpha(3, t2(d), t2(a2));
  }
  c.flag.assign(g.capacity(), 0);
  for (Dart d = 0; d < n && d < surface.flag.size(); ++d) c.flag[b(d)] = surface.flag[d];
  if (surface.positioned()) {
    // The corners (vertices with a flagged dart), or every vertex when none is flagged.
    bool any_flag = false;
    for (Dart d = 0; d < n && d < surface.flag.size(); ++d) any_flag |= surface.flag[d] != 0;
    Vec3 apex{0, 0, 0};
    size_t vertices = 0;
    for (Dart r : orbit_representatives(s, cell_type(s, 0))) {
      bool corner = !any_flag;
      for (Dart x : orbit(s, cell_type(s, 0), r))
        corner |= x < surface.flag.size() && surface.flag[x] != 0;
      if (!corner) continue;
      for (int k = 0; k < 3; ++k) apex[k] += surface.position[r][k];
      ++vertices;
    }
    for (int k = 0; k < 3; ++k) apex[k] /= double(vertices);
    c.position.assign(g.capacity(), apex);
    for (Dart d = 0; d < n; ++d)
      c.position[b(d)] = c.position[t0(d)] = c.position[t1(d)] = surface.position[d];
  }
  return c;
}

namespace {

// "hex-<split edges>[-f<cut faces>]" from a configuration's split list (cut face f is 100 + f).
std::string configuration_name(const std::vector<int>& split) {
  std::string edges, faces;
  for (int e : split) {
    if (e >= 100)
      faces += "-f" + std::to_string(e - 100);
    else
      edges += (edges.empty() ? "" : "_") + std::to_string(e);
  }
  return "hex-" + edges + faces;
}

}  // namespace

std::vector<Pattern> conformal_volume_patterns(Mode mode) {
  const ConfigurationSet set = generate_configurations("hex-conformal");
  std::unordered_set<Word, WordHash> seen;
  std::vector<Pattern> out;
  for (const Configuration& c : set.configurations) {
    std::vector<uint8_t> positive;
    if (mode == Mode::Oriented) positive = orientation_classes(c.map.map);
    if (!seen.insert(store_key(cell_boundary(c.map.map, 3, c.cell, c.map.flag, positive), 3, mode))
             .second)
      continue;
    out.push_back(make_pattern(configuration_name(c.split), cone_of_surface(c.map)));
  }
  return out;
}

}  // namespace gmr::replace
