// A symbolic concrete rule: the whole bounded family of rule_space.hpp as Z3 formulas
// (docs/verify.md, "Symbolic rules"), and the thesis conditions of Theorems 1-2 on it.
//
// Node slots 0..N-1. Slot x is in L (in_left) and/or in R (in_right): preserved, deleted or added
// (thesis Def. 24: the node map of a rule is a partial mono); a slot in neither does not exist.
// For every label i of `labels` and every pair of slots, arc(side, i, x, y) says that the side has
// the i-arc x -> y; on each side and label the arcs form a partial injection (at most one
// outgoing and one incoming i-arc per node), exactly the family of rule_space.hpp. Labels of the
// model outside `labels` carry no arcs. An L-arc is preserved iff R has the same arc (Assumption
// 4), deleted otherwise; an R-arc without L twin is added.
//
// Symmetry breaking (family()): the existing slots are a prefix 0..m-1, and their statuses are in
// nondecreasing order preserved < deleted < added (the family's status tuples). So the L nodes are
// the slots 0..|V_L|-1, which a match can send to darts 0..|V_L|-1 (symbolic_derivation.hpp).
//
// Conditions, as formulas (with `parts` switching parts off for the wrong variants):
//   combinatorial  Def. 35, second item: at most one i-arc out and in per L node (implied by the
//                  family's partial injections, asserted anyway);
//   w-I_r(i)       Def. 33: a preserved node has an outgoing (incoming) i-arc in L iff in R — with
//                  the multiplicity reading of checker/rule_check.hpp, here 0 or 1 on both sides;
//                  an added node has one outgoing and one incoming i-arc in R (a loop is both);
//   I_r(i)         Def. 34: w-I_r(i) and, for a deleted node, one outgoing and one incoming i-arc
//                  in L (the dangling part, Fact 1);
//   O_r(i)         Def. 37, on the involutive labels: every deleted (added) i-arc x -> y has the
//                  reverse y -> x, deleted (added) too (a loop is its own reverse; the reverse is
//                  unique in a partial injection).
// The cycle condition C_r (Def. 40) is not a formula here: symbolic_validation.hpp decides it
// lazily, the concrete checker being the oracle on the rule's nodes and cycle-label arcs.
#pragma once
#include <z3++.h>

#include <string>
#include <vector>

#include "checker/smt/condition_registry.hpp"
#include "model/core/map_spec.hpp"
#include "model/rewrite/rule.hpp"

namespace gmr::smt {

class SymbolicRule {
 public:
  SymbolicRule(z3::context& ctx, MapSpec spec, int max_nodes, std::vector<int> labels);

  z3::context& ctx() const { return ctx_; }
  const MapSpec& spec() const { return spec_; }
  int slots() const { return slots_; }
  const std::vector<int>& labels() const { return labels_; }

  const z3::expr& in_left(int x) const { return in_left_[x]; }
  const z3::expr& in_right(int x) const { return in_right_[x]; }
  z3::expr exists(int x) const { return in_left_[x] || in_right_[x]; }
  z3::expr preserved(int x) const { return in_left_[x] && in_right_[x]; }
  z3::expr deleted(int x) const { return in_left_[x] && !in_right_[x]; }
  z3::expr added(int x) const { return !in_left_[x] && in_right_[x]; }
  // The side has the i-arc x -> y (false for a label outside `labels`).
  z3::expr arc(bool right, int i, int x, int y) const;
  z3::expr deleted_arc(int i, int x, int y) const {
    return arc(false, i, x, y) && !arc(true, i, x, y);
  }
  z3::expr added_arc(int i, int x, int y) const {
    return arc(true, i, x, y) && !arc(false, i, x, y);
  }
  // The node has an outgoing (incoming) i-arc on the side.
  z3::expr has_out(bool right, int i, int x) const;
  z3::expr has_in(bool right, int i, int x) const;

  // The family's shape and the symmetry breaking, at least one node.
  z3::expr_vector family() const;
  // The rule has exactly m nodes (m existing slots).
  z3::expr nodes_exactly(int m) const;
  // The thesis conditions of Theorems 1-2 for every label of the model (parts switched off for the
  // wrong variants; `completion` has no effect here: the cycle condition is not part of it).
  z3::expr condition(const ThesisParts& parts) const;

  // The concrete rule of a model (nodes named a, b, c, ... after their slots, as rule_space.hpp).
  rewrite::Rule extract(const z3::model& m, const std::string& name) const;
  // "The rule variables equal those of the concrete rule r of the model" (to block or fix it).
  z3::expr equals(const z3::model& m) const;
  // "The node flags and the arcs on `labels` equal those of the rule of the model" (the other
  // labels' arcs are free).
  z3::expr equals_on(const z3::model& m, const std::vector<int>& labels) const;
  // "The rule variables describe r" (r's nodes named after slots a, b, c, ..., as rule_space.hpp
  // names them); Error(Usage) if r has another node name or an arc on a label outside `labels`.
  z3::expr describes(const rewrite::Rule& r) const;

 private:
  z3::context& ctx_;
  MapSpec spec_;
  int slots_;
  std::vector<int> labels_;
  std::vector<z3::expr> in_left_, in_right_;
  // arcs_[side][label index][x * slots + y]
  std::vector<std::vector<std::vector<z3::expr>>> arcs_;
  int label_index(int i) const;
};

}  // namespace gmr::smt
