// The symbolic-rule engine (checker/smt/symbolic_validation.hpp) against the rule-by-rule
// validation (condition_validation.hpp) with the enumerator: on the small bounds where both run,
// the same verdicts; the wrong variants refuted with counterexamples of the same size, which the
// enumerator confirms; the condition formulas equal the concrete checker on every rule of a family.
#include "checker/smt/symbolic_validation.hpp"

#include <gtest/gtest.h>

#include <string>

#include "checker/rule_check.hpp"
#include "checker/smt/condition_registry.hpp"
#include "checker/smt/condition_validation.hpp"
#include "checker/smt/rule_space.hpp"
#include "checker/smt/symbolic_rule.hpp"
#include "checker/smt/validation_format.hpp"
#include "model/core/error.hpp"

using namespace gmr;
using namespace gmr::smt;

namespace {
ValidationOptions sym_options(int n, MapKind kind, std::vector<int> labels, int max_nodes,
                              unsigned bound, Engine e = Engine::Enum) {
  return {.n = n,
          .kind = kind,
          .labels = std::move(labels),
          .max_nodes = max_nodes,
          .bound = bound,
          .engine = e};
}

ValidationReport family_report(const std::string& name, const ValidationOptions& o) {
  const BuiltinCondition* c = find_builtin_condition(name);
  return validate_condition(*c, o);
}

size_t rule_nodes(const Rule& r) { return r.left().num_nodes() + r.added_nodes().size(); }

// Both engines on one family: same verdicts; for an unsound condition, witnesses of the same
// size, and the symbolic witness breaks under the enumerator too.
void compare(const std::string& name, const ValidationOptions& o) {
  const SymbolicReport s = validate_symbolic(name, o);
  const ValidationReport f = family_report(name, o);
  std::printf("%s%s", to_text(s).c_str(), to_text(f).c_str());
  ASSERT_TRUE(s.sound_decided && s.complete_decided);
  EXPECT_EQ(s.sound(), f.sound()) << name;
  EXPECT_EQ(s.complete(), f.complete()) << name;
  EXPECT_EQ(s.rules, f.rules);
  if (s.smallest_unsound && f.smallest_unsound) {
    EXPECT_EQ(rule_nodes(s.smallest_unsound->rule), rule_nodes(f.smallest_unsound->rule));
    EXPECT_EQ(s.smallest_unsound->counterexample->G.size(),
              f.smallest_unsound->counterexample->G.size());
    const VerifyResult v = verify_enum(s.smallest_unsound->rule, o.bound, Semantics::Consistency);
    EXPECT_FALSE(v.preserves) << rule_text(s.smallest_unsound->rule);
    EXPECT_EQ(v.counterexample->G.size(), s.smallest_unsound->counterexample->G.size());
  }
  if (s.smallest_incomplete && f.smallest_incomplete) {
    EXPECT_EQ(rule_nodes(s.smallest_incomplete->rule), rule_nodes(f.smallest_incomplete->rule));
  }
}
}  // namespace

// The condition formulas of symbolic_rule.hpp are the checker's conditions, rule by rule, on every
// rule of the family (and every rule of the family satisfies the family's formulas).
TEST(SymbolicValidation, ConditionFormulasEqualTheCheckerOnEveryRule) {
  for (const auto& [n, kind, labels] : {std::tuple{1, MapKind::GMap, std::vector<int>{0, 1}},
                                        std::tuple{2, MapKind::OMap, std::vector<int>{1, 2}}}) {
    z3::context ctx;
    const SymbolicRule sym(ctx, MapSpec{n, kind}, 2, labels);
    z3::solver s(ctx);
    s.add(sym.family());
    const char* variants[] = {"thesis", "wrong-incident-without-dangling",
                              "wrong-orientation-dropped"};
    size_t rules = 0;
    for_each_rule(n, kind, 2, labels, [&](size_t k, const Rule& r) {
      s.push();
      s.add(sym.describes(r));
      EXPECT_EQ(s.check(), z3::sat)
          << "rule " << k << " is not in the symbolic family: " << rule_text(r);
      const z3::model m = s.get_model();
      for (const char* name : variants) {
        const bool formula = m.eval(sym.condition(*symbolic_condition_parts(name)), true).is_true();
        EXPECT_EQ(formula, find_builtin_condition(name)->holds(r))
            << name << " on " << rule_text(r);
      }
      EXPECT_EQ(sym.extract(m, "x").side(graph::Side::L).num_nodes(), r.left().num_nodes());
      s.pop();
      ++rules;
      return !::testing::Test::HasFailure();
    });
    EXPECT_EQ(rules, count_rules(1, 2) + count_rules(2, 2));
  }
}

TEST(SymbolicValidation, ThesisSoundAndComplete1GMapsAgreesWithEnumerator) {
  compare("thesis", sym_options(1, MapKind::GMap, {0, 1}, 2, 4));
}

TEST(SymbolicValidation, ThesisSoundAndComplete2OMapsAgreesWithEnumerator) {
  compare("thesis", sym_options(2, MapKind::OMap, {1, 2}, 2, 4));
}

// The dangling part dropped: a rule deleting a node without its arcs, on a map of 1 dart.
TEST(SymbolicValidation, WrongIncidentRefutedMinimally) {
  compare("wrong-incident-without-dangling", sym_options(1, MapKind::GMap, {0, 1}, 2, 4));
  const SymbolicReport s = validate_symbolic("wrong-incident-without-dangling",
                                             sym_options(1, MapKind::GMap, {0, 1}, 2, 4));
  ASSERT_TRUE(s.smallest_unsound);
  EXPECT_EQ(rule_nodes(s.smallest_unsound->rule), 1u);
  EXPECT_EQ(s.smallest_unsound->counterexample->G.size(), 1u);
  EXPECT_TRUE(s.smallest_unsound->counterexample->gluing_fails);
}

// O_r dropped: sound with 2 nodes (a permutation of two darts is an involution), refuted with 3
// nodes on a map of 3 darts.
TEST(SymbolicValidation, WrongOrientationRefutedWithThreeNodes) {
  compare("wrong-orientation-dropped", sym_options(1, MapKind::GMap, {0}, 2, 5));
  compare("wrong-orientation-dropped", sym_options(1, MapKind::GMap, {0}, 3, 5));
  const SymbolicReport s =
      validate_symbolic("wrong-orientation-dropped", sym_options(1, MapKind::GMap, {0}, 3, 5));
  ASSERT_TRUE(s.smallest_unsound);
  EXPECT_EQ(rule_nodes(s.smallest_unsound->rule), 3u);
  EXPECT_EQ(s.smallest_unsound->counterexample->G.size(), 3u);
  EXPECT_FALSE(s.smallest_unsound->counterexample->gluing_fails);
}

// Three nodes, two labels, 5 darts (34^4 rules with three preserved nodes): both engines agree.
TEST(SymbolicValidation, ThesisThreeNodes1GMapsAgreesWithFamilySmt) {
  const ValidationOptions o = sym_options(1, MapKind::GMap, {0, 1}, 3, 5, Engine::Smt);
  const SymbolicReport s = validate_symbolic("thesis", o);
  std::printf("%s", to_text(s).c_str());
  EXPECT_TRUE(s.sound() && s.complete());
}

TEST(SymbolicValidation, RefusesOtherConditions) {
  EXPECT_THROW(validate_symbolic("no-such", sym_options(1, MapKind::GMap, {0, 1}, 2, 4)), Error);
}

// The cycle oracle's lemmas generalise over the arcs of the labels outside the cycle pairs: on
// every fourth rule of the 2-G-map family (labels 0,1,2, up to 2 nodes), C_r in each reading is the
// same with the 1-arcs removed. (Where Theorems 1-2 hold, the validation itself checks every oracle
// verdict against the built-in condition.)
TEST(SymbolicValidation, CycleOracleReadsOnlyCycleLabels) {
  const std::vector<std::pair<std::string, CycleReading>> readings = {
      {"thesis", CycleReading::ModelCompletion},
      {"thesis-per-constraint", CycleReading::IjCompletion},
      {"wrong-cycle-without-completion", CycleReading::AsWritten}};
  size_t rules = 0, differ = 0;
  for_each_rule(2, MapKind::GMap, 2, {0, 1, 2}, [&](size_t k, const Rule& r) {
    if (k % 4 != 0) return true;  // a quarter of the family keeps the test fast
    graph::DGraph L = r.left(), R = r.right();
    for (graph::DGraph* g : {&L, &R})
      for (graph::ArcId a : g->arc_slots())
        if (g->arc_alive(a) && g->arc(a).label == 1) g->remove_arc(a);
    const Rule without1(std::move(L), std::move(R), 2, MapKind::GMap, "without 1-arcs");
    std::vector<bool> verdicts;
    for (const auto& [name, reading] : readings) {
      verdicts.push_back(cycle_condition(r, reading));
      EXPECT_EQ(verdicts.back(), cycle_condition(without1, reading))
          << name << " on " << rule_text(r);
    }
    if (verdicts.front() != verdicts.back()) ++differ;
    // No added node and no changed 0- or 2-arc: C_r holds in every reading (an axiom of the
    // symbolic queries).
    bool untouched = r.added_nodes().empty();
    for (graph::Side side : graph::kSides) {
      const graph::DGraph& g = r.side(side);
      for (graph::ArcId a : g.arc_slots())
        if (g.arc_alive(a) && g.arc(a).label != 1 &&
            r.arc_status(side, a) != graph::ElemStatus::Preserved)
          untouched = false;
    }
    if (untouched) {
      for (bool v : verdicts) EXPECT_TRUE(v) << rule_text(r);
    }
    ++rules;
    return !::testing::Test::HasFailure();
  });
  EXPECT_EQ(rules, (count_rules(1, 3) + count_rules(2, 3) + 3) / 4);
  EXPECT_GT(differ, 0u);  // the model completion matters on some rules
}

// Models with cycle pairs (2-G-maps, labels 0,1,2, up to 2 nodes): the cycle condition decided
// through the concrete checker's lemmas; both engines agree (the other built-in conditions, and
// bounds 5 and 6: proofs/symbolic_cycle_slow_proof.cpp).
TEST(SymbolicValidation, CycleModelsAgreeWithEnumerator) {
  for (const char* name : {"wrong-cycle-without-completion"})
    compare(name, sym_options(2, MapKind::GMap, {0, 1, 2}, 2, 4));
}

// The cycle condition without ij-completion is refuted (incomplete): the symbolic witness fails
// the condition, and the enumerator finds it applicable and preserving on every map of at most 5
// darts; the thesis condition (model completion) holds on it.
TEST(SymbolicValidation, WrongCycleWithoutCompletionRefutedConfirmedByEnumerator) {
  const ValidationOptions o = sym_options(2, MapKind::GMap, {0, 1, 2}, 2, 5);
  const SymbolicReport s = validate_symbolic("wrong-cycle-without-completion", o);
  std::printf("%s", to_text(s).c_str());
  ASSERT_TRUE(s.sound_decided && s.complete_decided);
  ASSERT_TRUE(s.smallest_incomplete);
  const Rule& w = s.smallest_incomplete->rule;
  EXPECT_EQ(rule_nodes(w), 2u);
  EXPECT_FALSE(find_builtin_condition("wrong-cycle-without-completion")->holds(w));
  EXPECT_TRUE(checker::check_rule(w).ok()) << rule_text(w);
  const VerifyResult v = verify_enum(w, o.bound, Semantics::Consistency);
  EXPECT_TRUE(v.applicable && v.preserves) << rule_text(w);
  const SymbolicReport t = validate_symbolic("thesis", o);
  EXPECT_TRUE(t.sound() && t.complete());
  EXPECT_GT(t.cycle_patterns, 0u);
  EXPECT_EQ(t.cycle_lemmas, 0u);  // every component of 2 nodes is tabulated
}

// The tabulated cycle condition (cycle_table.hpp) and the lemmas learnt lazily from the checker
// alone (no table) give the same verdicts and witnesses on 2-G-maps (labels 0, 1, 2, 2 nodes, 4
// darts) for every reading of C_r; the table needs no lemma, the lazy engine some.
TEST(SymbolicValidation, CycleTableAgreesWithLazyLemmas) {
  for (const char* name : {"thesis", "thesis-per-constraint", "wrong-cycle-without-completion"}) {
    ValidationOptions o = sym_options(2, MapKind::GMap, {0, 1, 2}, 2, 4);
    const SymbolicReport tab = validate_symbolic(name, o);
    o.cycle_table_nodes = 0;
    const SymbolicReport lazy = validate_symbolic(name, o);
    ASSERT_TRUE(tab.sound_decided && tab.complete_decided && lazy.sound_decided &&
                lazy.complete_decided);
    EXPECT_EQ(tab.sound(), lazy.sound()) << name;
    EXPECT_EQ(tab.complete(), lazy.complete()) << name;
    EXPECT_EQ(tab.smallest_incomplete.has_value(), lazy.smallest_incomplete.has_value()) << name;
    if (tab.smallest_incomplete && lazy.smallest_incomplete) {
      EXPECT_EQ(rule_nodes(tab.smallest_incomplete->rule),
                rule_nodes(lazy.smallest_incomplete->rule))
          << name;
    }
    EXPECT_GT(tab.cycle_patterns, 0u);
    EXPECT_EQ(tab.cycle_lemmas, 0u) << name;
    EXPECT_EQ(lazy.cycle_patterns, 0u);
    EXPECT_GT(lazy.cycle_lemmas, 0u) << name;
  }
}

// A condition that is too strong (the thesis conditions, and no L node with a 1-loop): incomplete,
// with a 1-node witness that the enumerator finds applicable and preserving on every map.
TEST(SymbolicValidation, TooStrongConditionIncompleteWitnessConfirmedByEnumerator) {
  const ValidationOptions o = sym_options(1, MapKind::GMap, {0, 1}, 2, 4);
  const SymbolicReport s = validate_symbolic(
      "thesis-without-1-loops", ThesisParts{},
      [](const SymbolicRule& r) {
        z3::expr_vector none(r.ctx());
        for (int x = 0; x < r.slots(); ++x) none.push_back(!r.arc(false, 1, x, x));
        return z3::mk_and(none);
      },
      o);
  std::printf("%s", to_text(s).c_str());
  ASSERT_TRUE(s.complete_decided);
  ASSERT_TRUE(s.smallest_incomplete);
  EXPECT_TRUE(s.sound());
  const Rule& w = s.smallest_incomplete->rule;
  EXPECT_EQ(rule_nodes(w), 1u);
  const VerifyResult v = verify_enum(w, o.bound, Semantics::Consistency);
  EXPECT_TRUE(v.applicable && v.preserves) << rule_text(w);
  // The rule-by-rule validation of the same condition is incomplete too, with a 1-node witness.
  ValidationOptions f = o;
  const ValidationReport fr = validate_condition(
      "thesis-without-1-loops",
      [](const std::vector<Rule>& rules) {
        std::vector<bool> out;
        for (const auto& r : rules) {
          bool loop = false;
          for (graph::ArcId a : r.left().arc_slots())
            loop = loop || (r.left().arc_alive(a) && r.left().arc(a).label == 1 &&
                            r.left().arc(a).src == r.left().arc(a).tgt);
          out.push_back(thesis_conditions(r) && !loop);
        }
        return out;
      },
      f);
  EXPECT_FALSE(fr.complete());
  ASSERT_TRUE(fr.smallest_incomplete);
  EXPECT_EQ(rule_nodes(fr.smallest_incomplete->rule), 1u);
}
