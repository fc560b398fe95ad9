// RapidCheck generators of concrete rules, described like maps by a small deterministic
// `RuleCase` (family, dimension, size, seed; corpus line "<family> <n> <size> <seed>"):
//   arbitrary rules
//     small, small-omap          random_small_rule: up to `size` (<= 3) nodes, each preserved,
//                                deleted or added, random partial injections per label (n = 1..3
//                                for G-maps, 2..3 for O-maps);
//     from-maps, from-maps-omap  random_rule_from_maps: L an induced subgraph of a small map
//                                (applicable), R one of another map (n = 1, 2; resp. 2);
//   consistent by construction
//     component, component-omap  component_replacement_rule: a whole small map replaced by another;
//     scheme-instance            a checker-accepted library scheme instantiated on the orbit of a
//                                random dart of a small map (n = 2, 3).
// The small map families are the exhaustive ones of checker/semantic.hpp (map_family(n, kind, 4)),
// computed once.
#pragma once
#include <rapidcheck.h>

#include <optional>
#include <ostream>
#include <string>

#include "checker/semantic.hpp"
#include "model/graph/map_family.hpp"
#include "model/rewrite/rule.hpp"

namespace gmr::prop {
using graph::MapFamily;
using rewrite::Rule;

enum class RuleFamily {
  Small,
  SmallOMap,
  FromMaps,
  FromMapsOMap,
  Component,
  ComponentOMap,
  SchemeInstance
};
const char* to_string(RuleFamily f);
MapKind kind_of(RuleFamily f);
bool consistent_by_construction(RuleFamily f);

struct RuleCase {
  RuleFamily family = RuleFamily::Small;
  int n = 2;
  size_t size = 1;
  uint64_t seed = 0;
  Rule build() const;
  std::string str() const;
  std::string corpus_line() const;
  static std::optional<RuleCase> parse(const std::string& line);
};

// The exhaustive family of maps with at most 4 darts (cached).
const MapFamily& small_maps(int n, MapKind kind);

rc::Gen<RuleCase> gen_rule_case(const std::vector<RuleFamily>& families);
rc::Gen<RuleCase> gen_arbitrary_rule_case();
rc::Gen<RuleCase> gen_consistent_rule_case();

std::string describe_rule(const Rule& r);
inline void showValue(const RuleCase& c, std::ostream& os) {
  os << c.str() << "\n" << describe_rule(c.build());
}

}  // namespace gmr::prop
