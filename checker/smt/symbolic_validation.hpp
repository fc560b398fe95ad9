// Validation of the built-in thesis conditions with the RULE symbolic too (docs/verify.md,
// "Symbolic rules"): instead of one SMT query per rule of the family (condition_validation.hpp),
// one query per direction covers every rule of at most N nodes at once.
//
//   sound     "is there a rule of the family (symbolic_rule.hpp), a map of at most k darts and a
//             match such that the condition holds and the match fails the gluing condition or H is
//             not a map?" UNSAT: sound for the whole family. SAT: the bounds are lowered (nodes,
//             then darts, with assumptions on the same solver) to the smallest witness, which is
//             replayed through the concrete derivation before it is reported.
//   complete  "is there a rule that fails the condition, matches some map of at most k darts, and
//             whose every match on every map of at most k darts glues and yields a map?" — a
//             forall over maps, solved by counterexample-guided refinement: a candidate rule (the
//             condition fails, a match on a symbolic witness map exists) is verified by the
//             concrete SMT engine (rule_verifier.hpp); if it breaks on (G, m), the constraint "the
//             match of the rule onto this G (relabelled so that m is the identity) glues and
//             preserves" is added to the candidate query, which must exclude the candidate
//             (checked; an encoding error otherwise). UNSAT: complete for the whole family. A
//             candidate that the concrete engine finds preserving is the witness (fewest nodes: the
//             node count is raised one by one, by assumptions).
// Conditions: the built-in ones. Theorems 1-2 are formulas on the symbolic rule
// (symbolic_rule.hpp). The cycle condition C_r (Defs. 38-40, read as the condition reads it: on the
// model completion, on the ij-completion, or as written) is a Boolean `cycle_holds` of both
// queries, tied lazily to the concrete checker (checker/cycle_check.cpp), which is the oracle:
// whenever a model satisfies Theorems 1-2 and its `cycle_holds` differs from the checker's verdict
// on its rule, the lemma "every rule with these node statuses and these arcs on the labels of
// the cycle pairs has C_r = verdict" is added and the query solved again. The lemma is valid for
// the whole family, since C_r reads nothing else (the completions and optimal paths of labels i, j
// use the arcs of i and j only); every final model therefore carries the true C_r of its rule, and
// UNSAT is a proof for the whole family. The number of lemmas is reported; each oracle verdict is
// cross-checked with the built-in condition itself. Before solving, the checker's verdicts on every
// component pattern of at most `cycle_table_nodes` nodes are tabulated and asserted as cubes
// (cycle_table.hpp, symbolic_cycle.hpp): lemmas are then learnt for larger components only.
#pragma once
#include <functional>
#include <optional>
#include <string>

#include "checker/smt/condition_registry.hpp"
#include "checker/smt/condition_validation.hpp"
#include "checker/smt/symbolic_rule.hpp"

namespace gmr::smt {

// The parts of a built-in condition for the symbolic engine; nullopt if it has no symbolic form.
std::optional<ThesisParts> symbolic_condition_parts(const std::string& name);

// How a built-in condition reads C_r: on the model completion (checker::check_rule), on the
// ij-completion of each pair (thesis-per-constraint), or on the rule as written (the wrong variant
// without ij-completion).
enum class CycleReading { ModelCompletion, IjCompletion, AsWritten };
CycleReading symbolic_cycle_reading(const std::string& name);
// C_r on every cycle pair of the rule's model, in that reading (true without cycle pairs).
bool cycle_condition(const Rule& r, CycleReading reading);

struct SymbolicReport {
  std::string condition;
  ValidationOptions options;  // n, kind, labels, max_nodes, bound, time_limit
  size_t rules = 0;           // of the family the verdicts cover (rule_space.hpp count)
  bool sound_decided = false, complete_decided = false;  // false: the time limit hit first
  std::optional<ValidationWitness> smallest_unsound, smallest_incomplete;
  size_t refinements = 0;     // maps added to the completeness query
  size_t cycle_lemmas = 0;    // verdicts of the concrete cycle checker added to the queries
  size_t cycle_patterns = 0;  // component patterns tabulated before solving (cycle_table.hpp)
  size_t cycle_cubes = 0;  // cubes of the table: failing (both queries) and holding (completeness)
  double cycle_table_seconds = 0;
  double sound_seconds = 0, complete_seconds = 0;
  bool sound() const { return sound_decided && !smallest_unsound; }
  bool complete() const { return complete_decided && !smallest_incomplete; }
};

// Error(Usage) for a condition without symbolic form.
SymbolicReport validate_symbolic(const std::string& condition, const ValidationOptions& opt);
// The condition "parts, and extra(rule) when given" (a further formula on the symbolic rule: the
// tests use it to build a condition that is too strong).
using ExtraCondition = std::function<z3::expr(const SymbolicRule&)>;
SymbolicReport validate_symbolic(const std::string& condition, const ThesisParts& parts,
                                 const ExtraCondition& extra, const ValidationOptions& opt);

}  // namespace gmr::smt
