// The --match syntax of `gmr apply` ("a=3,b=5") against a four-node rule and a 48-dart map.
#include "model/rule_io/rule_json.hpp"
#include "tools/cli/match_syntax.hpp"
#include "tools/fuzzing/fuzz_target.hpp"

void gmr::fuzzing::fuzz_one(std::string_view text) {
  static const rewrite::Rule rule =
      io::parse_rule(R"({"format": "gmr.rule", "version": 1, "kind": "concrete",
    "name": "unsew", "map": "gmap", "n": 2,
    "left": {"nodes": ["a", "b", "c", "d"], "links": [{"nodes": ["a", "b"], "label": 0}]},
    "right": {"nodes": ["a", "b", "c", "d"], "links": [{"nodes": ["a", "b"], "label": 0}]}})");
  static const Map map = [] {
    Map g(2);
    g.add_darts(48);
    return g;
  }();
  const auto pairs = cli::parse_match_pairs(rule, map, std::string(text));
  for (const auto& [node, dart] : pairs)
    if (node.index() >= rule.left().num_nodes() || !map.alive(dart))
      __builtin_trap();  // only valid pairs pass
}
