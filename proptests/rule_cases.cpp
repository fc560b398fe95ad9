#include "proptests/rule_cases.hpp"

#include <map>

#include "model/draw/rule_dot.hpp"
#include "model/rule_io/rule_json.hpp"
#include "model/scheme/scheme_instantiation.hpp"
#include "model/testing/random_maps.hpp"
#include "model/testing/rule_family.hpp"
#include "proptests/case_line.hpp"
#include "proptests/library.hpp"

namespace gmr::prop {
using namespace gmr::graph;
using namespace gmr::rewrite;
using namespace gmr::scheme;
using namespace gmr::io;
using namespace gmr::draw;
using namespace gmr::testing;

namespace {

constexpr RuleFamily kAll[] = {RuleFamily::Small,         RuleFamily::SmallOMap,
                               RuleFamily::FromMaps,      RuleFamily::FromMapsOMap,
                               RuleFamily::Component,     RuleFamily::ComponentOMap,
                               RuleFamily::SchemeInstance};

// Dimensions a family is drawn in.
std::pair<int, int> dims_of(RuleFamily f) {
  switch (f) {
    case RuleFamily::Small:
      return {1, 3};
    case RuleFamily::SmallOMap:
      return {2, 3};
    case RuleFamily::FromMaps:
    case RuleFamily::Component:
      return {1, 2};
    case RuleFamily::FromMapsOMap:
    case RuleFamily::ComponentOMap:
      return {2, 2};
    case RuleFamily::SchemeInstance:
      return {2, 3};
  }
  return {2, 2};
}

Rule scheme_instance(Rng& rng, int n, size_t size) {
  const std::vector<size_t> lib = library_of_dim(n, true);
  const RuleScheme& s = scheme_library()[lib[uniform(rng, 0, lib.size() - 1)]].scheme;
  Map g(n);
  if (n == 3) {
    PolycubeOptions o;
    o.max_voxels = 1 + size % 2;
    g = random_polycube(rng, o);
  } else {
    GluedPolygonsOptions o;
    o.max_faces = size;
    o.max_extra_sews = size;
    g = random_glued_polygons(rng, o);
  }
  const auto darts = g.darts();
  Rule r = instantiate_rule(s, hook_orbit_graph(g, s, darts[uniform(rng, 0, darts.size() - 1)]));
  return r;
}

}  // namespace

const char* to_string(RuleFamily f) {
  switch (f) {
    case RuleFamily::Small:
      return "small";
    case RuleFamily::SmallOMap:
      return "small-omap";
    case RuleFamily::FromMaps:
      return "from-maps";
    case RuleFamily::FromMapsOMap:
      return "from-maps-omap";
    case RuleFamily::Component:
      return "component";
    case RuleFamily::ComponentOMap:
      return "component-omap";
    case RuleFamily::SchemeInstance:
      return "scheme-instance";
  }
  return "?";
}

MapKind kind_of(RuleFamily f) {
  return f == RuleFamily::SmallOMap || f == RuleFamily::FromMapsOMap ||
                 f == RuleFamily::ComponentOMap
             ? MapKind::OMap
             : MapKind::GMap;
}

bool consistent_by_construction(RuleFamily f) {
  return f == RuleFamily::Component || f == RuleFamily::ComponentOMap ||
         f == RuleFamily::SchemeInstance;
}

const MapFamily& small_maps(int n, MapKind kind) {
  static std::map<std::pair<int, MapKind>, MapFamily> cache;
  auto it = cache.find({n, kind});
  if (it == cache.end()) it = cache.emplace(std::make_pair(n, kind), map_family(n, kind, 4)).first;
  return it->second;
}

Rule RuleCase::build() const {
  Rng rng(seed);
  const MapKind kind = kind_of(family);
  switch (family) {
    case RuleFamily::Small:
    case RuleFamily::SmallOMap:
      return random_small_rule(rng, n, kind, static_cast<int>(std::min<size_t>(size, 3)));
    case RuleFamily::FromMaps:
    case RuleFamily::FromMapsOMap:
      return random_rule_from_maps(rng, small_maps(n, kind), std::min<size_t>(size, 4));
    case RuleFamily::Component:
    case RuleFamily::ComponentOMap:
      return component_replacement_rule(rng, small_maps(n, kind));
    case RuleFamily::SchemeInstance:
      return scheme_instance(rng, n, size);
  }
  throw std::logic_error("unknown rule family");
}

std::string RuleCase::str() const { return "RuleCase{" + corpus_line() + "}"; }

std::string RuleCase::corpus_line() const {
  return CaseLine{to_string(family), n, size, seed}.str();
}

std::optional<RuleCase> RuleCase::parse(const std::string& line) {
  const auto l = CaseLine::parse(line);
  if (!l) return std::nullopt;
  for (RuleFamily f : kAll)
    if (l->family == to_string(f)) {
      const auto [lo, hi] = dims_of(f);
      if (l->n < lo || l->n > hi) return std::nullopt;
      return RuleCase{f, l->n, l->size, l->seed};
    }
  return std::nullopt;
}

rc::Gen<RuleCase> gen_rule_case(const std::vector<RuleFamily>& families) {
  return rc::gen::mapcat(rc::gen::elementOf(families), [](RuleFamily f) {
    const auto [lo, hi] = dims_of(f);
    return rc::gen::apply(
        [f](int n, size_t size, uint64_t seed) {
          return RuleCase{f, n, size, seed};
        },
        rc::gen::inRange(lo, hi + 1), rc::gen::inRange<size_t>(1, 4),
        rc::gen::inRange<uint64_t>(0, 1u << 20));
  });
}

rc::Gen<RuleCase> gen_arbitrary_rule_case() {
  return gen_rule_case(
      {RuleFamily::Small, RuleFamily::SmallOMap, RuleFamily::FromMaps, RuleFamily::FromMapsOMap});
}

rc::Gen<RuleCase> gen_consistent_rule_case() {
  return gen_rule_case(
      {RuleFamily::Component, RuleFamily::ComponentOMap, RuleFamily::SchemeInstance});
}

std::string describe_rule(const Rule& r) {
  return "--- rule (gmr.rule) ---\n" + rule_to_json(r).dump(2) + "\n--- diagram (DOT) ---\n" +
         to_dot(r);
}

}  // namespace gmr::prop
