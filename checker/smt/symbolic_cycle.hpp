// The cycle condition C_r on a symbolic rule, by components (docs/verify.md, "The cycle condition
// by components"; proofs/README.md, "C_r by components").
//
// For every nonempty set S of slots (a bit mask), `component(S)` says that the slots of S exist and
// form one connected component under the arcs of the cycle labels (either side, either direction),
// and the Boolean `ok(S)` stands for C_r of the rule restricted to S (cycle_components.hpp). The
// axioms tie them to `cycle_holds`:
//
//   guard => (cycle_holds <=> AND_S (component(S) => ok(S)))     (guard: w-I_r and more, see below)
//   component(S), no added node and no changed cycle-label arc in S  =>  ok(S)
//
// The first is the decomposition of cycle_components.hpp, valid on the rules with w-I_r on the
// cycle labels (the family's L and R are partial injections); the caller's guard must imply it.
// The second holds in every reading (the completions add preserved arcs only: no optimal path, no
// rewired node, no added node in S). `ok(S)` is learnt from the concrete checker, lazily: a lemma
// "every placement of this component's pattern (node statuses and cycle-label arcs) on any slots
// has ok = the checker's verdict on the component" holds for the whole family because C_r of a
// component does not depend on the names or order of its nodes. Placements that break the
// family's status order (preserved < deleted < added along the slots) are left out: no rule of the
// family has them. With one cycle pair {i, j} (2-G-maps), the pattern with the labels i and j
// swapped is placed too: C_r treats both labels of a pair alike.
#pragma once
#include <z3++.h>

#include <string>
#include <vector>

#include "checker/smt/cycle_table.hpp"
#include "checker/smt/symbolic_rule.hpp"
#include "model/rewrite/rule.hpp"

namespace gmr::smt {

class SymbolicCycle {
 public:
  SymbolicCycle(const SymbolicRule& rule, std::vector<int> cycle_labels);

  const std::vector<int>& labels() const { return labels_; }
  z3::expr component(unsigned mask) const;
  const z3::expr& ok(unsigned mask) const { return ok_[mask]; }
  // The two axioms above, the first under `guard`.
  z3::expr_vector axioms(const z3::expr& guard, const z3::expr& cycle_holds) const;
  // The slot mask of a set of nodes of a rule extracted from the symbolic rule (nodes named after
  // their slots: a, b, c, ...).
  unsigned mask_of(const std::vector<std::string>& nodes) const;
  // "Every placement of the pattern that the slots of `mask` have in m has ok = verdict".
  z3::expr lemma(const z3::model& m, unsigned mask, bool verdict) const;
  // The table's verdicts as lemmas, exactly (the engine asserts the smaller cube_lemmas; this form
  // is the reference the tests compare them with): for every pattern of k nodes and every
  // set S of k slots, "the slots of S, in order, carry the pattern => ok(S) = its verdict" (the
  // order-preserving placement keeps the family's status order; the table holds every labelling
  // of the pattern's nodes, so every placement of a component is one of these). Each pattern is
  // the cube fixing all its variables, given to cube_lemmas with the guard true.
  z3::expr_vector table_lemmas(const CycleTable& table) const;
  // The cubes as lemmas: for every cube of k nodes and every set S of k slots, "guard and the
  // slots of S, in order, lie in the cube => ok(S) = the cube's verdict". Valid when the guard
  // implies Theorems 1-2 (every component of such a rule is a pattern of the table, and a cube
  // holds no pattern of the other verdict): the soundness query asserts the failing cubes with
  // the guard true (Theorems 1-2 are asserted there), the completeness query both kinds under a
  // literal equal to Theorems 1-2.
  z3::expr_vector cube_lemmas(const CycleTable& table, const std::vector<PatternCube>& cubes,
                              const z3::expr& guard) const;

 private:
  const SymbolicRule& rule_;
  std::vector<int> labels_;
  std::vector<z3::expr> ok_;  // indexed by mask; ok_[0] unused
  // Some cycle-label arc, on either side, either direction, between the slots x and y.
  z3::expr linked(int x, int y) const;
  // The slot has no status change and its cycle-label arcs to the slots of mask are unchanged.
  z3::expr untouched(int x, unsigned mask) const;
};

}  // namespace gmr::smt
