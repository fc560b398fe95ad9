// Validation of a condition on concrete rules against the DPO semantics (docs/verify.md):
// over every rule of the bounded family (rule_space.hpp: up to `max_nodes` nodes, arcs on
// `labels`) and every map of the model with at most `bound` darts:
//   unsound     the condition holds, but some match of the rule on some map fails the gluing
//               condition or its derivation breaks a constraint (Semantics::Consistency);
//   incomplete  the condition fails, yet the rule matches some map within the bound and every
//               such match glues and yields a map of the model;
//   vacuous     the rule matches no map within the bound: counted, neither.
// Optionally, random larger rules follow (counted with the others; not in `nodes_covered`).
// The condition is sound (resp. complete) within the bound when no rule is unsound (resp.
// incomplete). The smallest witness each way is kept: fewest rule nodes, then fewest darts (for an
// unsound rule), then first in the family's order.
//
// Sharding: shard K of M takes the rules whose index in the family is K mod M, so the shards of
// one sweep partition it (their counts add up; the smallest witness is the least of the shards').
// A time limit stops the sweep between rules; the report then says which rules were covered: all
// rules with at most `nodes_covered` nodes (of this shard), and how many in all.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "checker/smt/condition_registry.hpp"
#include "checker/smt/rule_verifier.hpp"

namespace gmr::smt {

struct ValidationOptions {
  int n = 1;
  MapKind kind = MapKind::GMap;
  std::vector<int> labels;  // labels carrying arcs in the family
  int max_nodes = 2;
  unsigned bound = 4;
  Engine engine = Engine::Smt;
  unsigned shard = 0, shards = 1;
  double time_limit = 0;  // seconds; 0: none
  // Random larger rules after the family: `random` rules of max_nodes+1 or max_nodes+2 nodes
  // (rule_space.hpp random_rule) from generator seed `seed`; their indices follow the family's.
  size_t random = 0;
  uint64_t seed = 1;
  // Called now and then with (rules done, rules of the shard).
  std::function<void(size_t, size_t)> progress{};
  // Symbolic engine: components of at most this many nodes have C_r tabulated before solving
  // (cycle_table.hpp); larger ones are learnt from the checker lazily (0: all lazily).
  int cycle_table_nodes = 4;
};

struct ValidationWitness {
  Rule rule;
  size_t index = 0;                              // in the family
  std::optional<Counterexample> counterexample;  // unsound: the breaking match
};

struct ValidationReport {
  std::string condition;
  ValidationOptions options;
  size_t rules = 0;    // of the shard
  size_t checked = 0;  // verified before the time limit
  size_t holds = 0, fails = 0, vacuous = 0, unsound = 0, incomplete = 0;
  int nodes_covered = 0;  // every rule of the shard with at most this many nodes was checked
  bool time_limit_hit = false;
  std::optional<ValidationWitness> smallest_unsound, smallest_incomplete;
  double seconds = 0, condition_seconds = 0;
  bool sound() const { return unsound == 0; }
  bool complete() const { return incomplete == 0; }
};

// `evaluate` returns holds(rule) for every rule of the list (in-process, or a plug-in's child).
using ConditionEvaluator = std::function<std::vector<bool>(const std::vector<Rule>&)>;
ValidationReport validate_condition(const std::string& name, const ConditionEvaluator& evaluate,
                                    const ValidationOptions& opt);
// The same for a built-in condition (condition_registry.hpp), evaluated in process rule by rule.
ValidationReport validate_condition(const BuiltinCondition& c, const ValidationOptions& opt);

}  // namespace gmr::smt
