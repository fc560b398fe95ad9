#include "proptests/generators.hpp"

#include <algorithm>

#include "model/draw/map_dot.hpp"
#include "model/graph/dgraph.hpp"
#include "model/map_io/map_json.hpp"
#include "proptests/case_line.hpp"
#include "proptests/library.hpp"

namespace gmr::prop {
using namespace gmr::graph;
using namespace gmr::scheme;
using namespace gmr::io;
using namespace gmr::draw;
using namespace gmr::testing;

namespace {

constexpr Family kAll[] = {Family::GluedPolygons,    Family::Polycube,        Family::SewSequence,
                           Family::RuleApplications, Family::PermutationOMap, Family::Oriented};

// A small map edited by `steps` random applications of accepted library schemes of dimension n
// (2 or 3) at random hook darts; refused applications are skipped, and the map is kept under
// ~600 darts (quad subdivision of a whole component multiplies it by 4).
Map rule_applications(Rng& rng, int n, size_t steps) {
  Map g(n);
  if (n == 3) {
    PolycubeOptions o;
    o.max_voxels = 2;
    g = random_polycube(rng, o);
  } else {
    GluedPolygonsOptions o;
    o.n = n;
    o.max_faces = 2;
    o.max_extra_sews = 1;
    g = random_glued_polygons(rng, o);
  }
  const std::vector<size_t> lib = library_of_dim(n, true);
  if (lib.empty()) return g;
  for (size_t s = 0; s < steps; ++s) {
    const LibraryScheme& ls = scheme_library()[lib[uniform(rng, 0, lib.size() - 1)]];
    const RuleScheme& sch = ls.scheme;
    const auto darts = g.darts();
    std::vector<Dart> hooks;
    for (size_t h = 0; h < sch.hooks.size(); ++h)
      hooks.push_back(darts[uniform(rng, 0, darts.size() - 1)]);
    Map h = g;
    if (scheme::apply(*ls.engine, h, hooks).applied && h.size() <= 600 && h.size() > 0)
      g = to_map(to_dgraph(h), n);  // renumbers the live darts densely
  }
  return g;
}

}  // namespace

const char* to_string(Family f) {
  switch (f) {
    case Family::GluedPolygons:
      return "glued-polygons";
    case Family::Polycube:
      return "polycube";
    case Family::SewSequence:
      return "sew-sequence";
    case Family::RuleApplications:
      return "rule-applications";
    case Family::PermutationOMap:
      return "permutation-omap";
    case Family::Oriented:
      return "oriented";
  }
  return "?";
}

std::optional<Family> parse_family(const std::string& s) {
  for (Family f : kAll)
    if (s == to_string(f)) return f;
  return std::nullopt;
}

bool is_omap_family(Family f) { return f == Family::PermutationOMap || f == Family::Oriented; }

std::vector<Family> families_for(int n, bool omap) {
  std::vector<Family> out;
  if (omap) {
    if (n == 2) out.push_back(Family::PermutationOMap);
    if (n == 2 || n == 3) out.push_back(Family::Oriented);
    return out;
  }
  if (n >= 2) out.push_back(Family::GluedPolygons);
  if (n == 3) out.push_back(Family::Polycube);
  out.push_back(Family::SewSequence);
  if (n == 2 || n == 3) out.push_back(Family::RuleApplications);
  return out;
}

Map MapCase::build() const {
  Rng rng(seed);
  switch (family) {
    case Family::GluedPolygons: {
      GluedPolygonsOptions o;
      o.n = n;
      o.min_faces = 1;
      o.max_faces = size;
      o.max_extra_sews = size;
      return random_glued_polygons(rng, o);
    }
    case Family::Polycube: {
      PolycubeOptions o;
      o.min_voxels = 1;
      o.max_voxels = size;
      return random_polycube(rng, o);
    }
    case Family::SewSequence: {
      SewSequenceOptions o;
      o.n = n;
      o.min_cells = 1;
      o.max_cells = size;
      o.steps = 3 * size;
      return random_sewn_cells(rng, o);
    }
    case Family::RuleApplications:
      return rule_applications(rng, n, size);
    case Family::PermutationOMap: {
      PermutationOMapOptions o;
      o.max_darts = 2 * size;
      return random_permutation_omap(rng, o);
    }
    case Family::Oriented: {
      if (n == 3) {
        PolycubeOptions o;
        o.max_voxels = size;
        return oriented_components(double_along_boundary(random_polycube(rng, o)));
      }
      GluedPolygonsOptions o;
      o.n = n;
      o.max_faces = size;
      o.max_extra_sews = size;
      return oriented_components(random_glued_polygons(rng, o));
    }
  }
  return Map(n);
}

std::string MapCase::str() const { return "MapCase{" + corpus_line() + "}"; }

std::string MapCase::corpus_line() const {
  return CaseLine{to_string(family), n, size, seed}.str();
}

std::optional<MapCase> MapCase::parse(const std::string& line) {
  const auto l = CaseLine::parse(line);
  const auto f = l ? parse_family(l->family) : std::nullopt;
  if (!f) return std::nullopt;
  const auto fits = families_for(l->n, is_omap_family(*f));
  if (std::find(fits.begin(), fits.end(), *f) == fits.end()) return std::nullopt;
  return MapCase{*f, l->n, l->size, l->seed};
}

namespace {

rc::Gen<MapCase> gen_case_of_dim(int n, size_t max_size, bool omap) {
  const auto families = families_for(n, omap);
  return rc::gen::apply(
      [n, families](size_t fam, size_t size, uint64_t seed) {
        return MapCase{families[fam], n, size, seed};
      },
      rc::gen::inRange<size_t>(0, families.size()), rc::gen::inRange<size_t>(1, max_size + 1),
      rc::gen::inRange<uint64_t>(0, 1u << 20));
}

}  // namespace

rc::Gen<MapCase> gen_map_case_of_dim(int n, size_t max_size) {
  return gen_case_of_dim(n, max_size, false);
}

rc::Gen<MapCase> gen_map_case(size_t max_size) {
  return rc::gen::mapcat(rc::gen::inRange(1, 4),
                         [max_size](int n) { return gen_map_case_of_dim(n, max_size); });
}

rc::Gen<MapCase> gen_omap_case_of_dim(int n, size_t max_size) {
  return gen_case_of_dim(n, max_size, true);
}

rc::Gen<MapCase> gen_omap_case(size_t max_size) {
  return rc::gen::mapcat(rc::gen::inRange(2, 4),
                         [max_size](int n) { return gen_omap_case_of_dim(n, max_size); });
}

rc::Gen<OrbitType> gen_orbit_type(int n) {
  return rc::gen::map(rc::gen::inRange<uint32_t>(0, 1u << (n + 1)), [n](uint32_t mask) {
    std::vector<int> dims;
    for (int i = 0; i <= n; ++i)
      if (mask >> i & 1u) dims.push_back(i);
    return OrbitType(std::move(dims));
  });
}

rc::Gen<std::vector<Dart>> gen_permutation(size_t k) {
  return rc::gen::map(rc::gen::arbitrary<uint64_t>(), [k](uint64_t seed) {
    Rng rng(seed);
    return random_permutation(rng, k);
  });
}

std::string describe_counterexample(const Map& g) {
  std::string s = "--- counterexample (gmr.gmap) ---\n" + write_map_json(g, {});
  s += "\n--- diagram (DOT) ---\n" + to_dot(g);
  return s;
}

}  // namespace gmr::prop
