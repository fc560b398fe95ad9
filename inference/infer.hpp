// The inference driver (thesis §7.3.2): every orbit type (or one), every start
// dart, marking of equivalent starts, de-duplication by rule-scheme isomorphism.
//
// For each orbit type <o> (the given one, or all 2^(n+1) subsets of 0..n, by increasing size, then
// lexicographically: <>, <0>, <1>, ..., <0,1,...,n>), for each L dart a of the joint graph in
// increasing index order that is not marked for <o>:
//   fold(J, <o>, a) (fold.hpp) — or, with all_relabelings, every fold over the combinations of
//   consistent relabelings (fold_all), each processed as below; then mark (a documented choice, the
//   thesis leaving it open):
//    * the whole hook orbit J<o>(a): instantiation does not depend on which dart of O is the
//      start, so every dart of O would give the same answer;
//    * after a success or a failure, also the darts of every L node whose decoration has no `_`
//      and whose set is <o> (equivalent_starts). After a success, starting there roots the same
//      rule at another hook. After a failure, a scheme from such a start x would contain, through
//      the explicit arcs of the fold's path from a to x read backwards, J<o>(a) as a node, and
//      rooted there it would be a scheme from a, which folding (complete, App. C) did not find;
//      the argument assumes that node's decoration full, and completeness_test.cpp checks the
//      claim exhaustively on small maps. Each start is then folded about once per node class
//      instead of once per orbit, which makes a failing orbit type cost about what one fold visits;
//   a successful fold becomes a rule (rule_from_fold.hpp); an accepted rule is kept unless it is
//   isomorphic (scheme_isomorphism.hpp, up to a permutation of positions) to one already kept, in
//   which case it is counted as a duplicate of that one.
// Every attempt is recorded (for the summary table): orbit type, start dart, outcome, numbers of L
// and R nodes, the checker's verdict, the rule it duplicates.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "inference/fold.hpp"
#include "inference/rule_from_fold.hpp"

namespace gmr::inference {

struct InferOptions {
  std::optional<OrbitType> orbit;  // none: every orbit type
  FoldOptions fold;
  RuleOptions rule;  // posterior-cut loops
  // Plurality of answers (thesis §7.6): fold every combination of consistent relabelings
  // (fold_all, at most relabeling_limit folds per start dart) instead of the default choice only.
  bool all_relabelings = false;
  size_t relabeling_limit = 1000;
  // Called after each orbit type (index, count, the orbit type) — for progress on a terminal.
  std::function<void(size_t, size_t, const OrbitType&)> progress;
};

enum class AttemptOutcome { FoldFailed, NoHook, Inconsistent, Accepted, Duplicate };
const char* to_string(AttemptOutcome o);

struct InferAttempt {
  OrbitType orbit;
  uint32_t start = 0;      // joint-graph dart
  std::string start_text;  // as users see it ("before 7")
  AttemptOutcome outcome = AttemptOutcome::FoldFailed;
  FoldFailure failure;  // FoldFailed
  size_t left_nodes = 0, right_nodes = 0;
  std::string reason;  // NoHook / Inconsistent: why; FoldFailed: the failure message
  int rule = -1;       // Accepted: index in InferenceResult::rules; Duplicate: the rule it equals
  std::optional<InferredRule> rejected;  // NoHook / Inconsistent: the rule and the checker's report
};

struct InferenceResult {
  std::vector<InferredRule> rules;  // accepted, pairwise non-isomorphic
  std::vector<size_t> duplicates;   // duplicates[k]: attempts merged into rules[k]
  std::vector<InferAttempt> attempts;
  bool truncated = false;  // all_relabelings: some start dart reached relabeling_limit
};

// The starts a fold makes redundant for its orbit type (the marking above, after a success or a
// failure): the darts of every L node whose decoration has no `_` and has the set of <o>, the hook
// orbit included (joint-graph darts).
std::vector<uint32_t> equivalent_starts(const FoldResult& f);

// Orbit types tried when none is given.
std::vector<OrbitType> all_orbit_types(int n);

InferenceResult infer_rules(const JointGraph& j, const InferOptions& opt = {});

}  // namespace gmr::inference
