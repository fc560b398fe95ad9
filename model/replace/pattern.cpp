#include "model/replace/pattern.hpp"

#include "model/core/error.hpp"
#include "model/core/orbit.hpp"
#include "model/core/position.hpp"
#include "model/core/validity.hpp"
#include "model/replace/orientation.hpp"

namespace gmr::replace {

Pattern make_pattern(std::string name, FlaggedMap m) {
  auto reject = [&](const std::string& why) {
    throw Error(ErrorCode::Schema, "not a pattern: " + why, name);
  };
  const Map& g = m.map;
  const int n = g.dimension();
  if (g.is_omap()) reject("patterns are G-maps");
  if (n != 2 && n != 3)
    reject("an f-pattern is a 2-G-map and a v-pattern a 3-G-map (dimension " + std::to_string(n) +
           ")");
  if (g.size() == 0) reject("no dart");
  const ValidityReport v = check_validity(g, 1);
  if (!v.ok()) reject("invalid G-map: " + to_text(v.violations.front()));
  if (count_components(g) != 1) reject("not connected");
  size_t boundary = 0;
  g.for_each_dart([&](Dart d) {
    for (int i = 0; i < n; ++i)
      if (g.is_free(i, d))
        reject("dart " + std::to_string(d) + " is " + std::to_string(i) +
               "-free (only the boundary, " + std::to_string(n) + "-free darts, may be free)");
    boundary += g.is_free(n, d);
  });
  if (boundary == 0) reject("no boundary (no " + std::to_string(n) + "-free dart)");
  Pattern p;
  p.name = name;
  p.cell_dim = n;
  p.interior = g.size() - boundary;
  try {
    p.positive = orientation_classes(g);
  } catch (const Error&) {
    p.positive.clear();
  }
  m.resize_flags();
  p.boundary = pattern_boundary(g, m.flag, p.positive);
  if (!is_connected(p.boundary))
    reject(n == 2 ? "the boundary is not one cycle (not a disc)"
                  : "the boundary is not one connected surface");
  if (m.positioned() && !p.positive.empty())
    p.interior_vertices = mean_value_coordinates(g, m.position, p.positive);
  g.for_each_dart([&](Dart d) {
    if (!g.is_free(n, d)) p.interior_darts.push_back(d);
  });
  p.vertex_of.assign(g.capacity(), UINT32_MAX);
  for (Dart rep : orbit_representatives(g, vertex_orbit_type(g))) {
    Dart anchor = kNoDart;
    for (Dart y : orbit(g, vertex_orbit_type(g), rep)) {
      p.vertex_of[y] = static_cast<uint32_t>(p.vertex_anchor.size());
      if (anchor == kNoDart && g.is_free(n, y)) anchor = y;
    }
    p.vertex_anchor.push_back(anchor);
  }
  p.map = std::move(m);
  return p;
}

}  // namespace gmr::replace
