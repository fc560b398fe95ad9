// From a folded joint representation to a rule scheme (thesis §7.3.1).
//
//  1. nodes are split by side; 2. κ-arcs become preserved-node pairs (both ends share one name);
//  3. κ-arcs are deleted, leaving the graph schemes L and R; 4. hooks: the fold's hook h for its L
//  component and, for every other L component, a node with a full decoration (no `_`) — the one
//  whose decoration equals <o> if any, otherwise the first in creation order (the thesis says "at
//  random"; this choice is deterministic). A component without such a node rejects the rule;
//  5. the scheme checker (checker/scheme_checker.hpp) runs; an inconsistent scheme is rejected with
//  its diagnostics (thesis §7.2.4: a foldable scheme can be topologically invalid).
//
// Posterior-cut loops (thesis §7.3, Jerboa's parameter; the side it applies to is a documented
// choice): for the dimensions of `cut_loops`, an explicit d-loop on a PRESERVED node that is
// present on both sides is removed from both sides (the only safe reading: the rule then neither
// requires nor touches the d-links of that node, instead of demanding free cells). A loop only in L
// or only in R is kept (removing it would change what the rule does).
//
// Names (deterministic): L nodes n0, n1, ... in fold creation order (n0 is the hook); an R node
// κ-paired with an L node takes its name; the other R nodes continue the numbering in creation
// order. Each node keeps the darts it stands for (the thesis' node -> darts association).
#pragma once
#include <string>
#include <vector>

#include "checker/scheme_checker.hpp"
#include "inference/fold.hpp"
#include "model/scheme/rule_scheme.hpp"

namespace gmr::inference {
using checker::CheckReport;
using scheme::RuleScheme;

enum class RuleVerdict { Accepted, NoHook, Inconsistent };
const char* to_string(RuleVerdict v);  // "accepted", "no hook", "rejected by the checker"

struct InferredRule {
  RuleScheme scheme;
  RuleVerdict verdict = RuleVerdict::Accepted;
  std::string reason;  // empty when accepted
  CheckReport check;   // the checker's report (empty for NoHook)
  // Darts (origin ids in the before / after map) of each node, indexed like scheme.left/right
  // nodes, darts[b] for orbit dart b.
  std::vector<std::vector<Dart>> left_darts, right_darts;
  OrbitType orbit;
  Dart start = 0;  // origin id of the start dart
  bool accepted() const { return verdict == RuleVerdict::Accepted; }
};

// `f` must be a successful fold of `j`. `name` becomes the scheme's name.
struct RuleOptions {
  DimMask cut_loops = 0;
};

InferredRule rule_from_fold(const FoldResult& f, const JointGraph& j,
                            const std::string& name = "inferred", const RuleOptions& opt = {});

}  // namespace gmr::inference
