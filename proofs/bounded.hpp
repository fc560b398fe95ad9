// Shared driver of the bounded proofs (proofs/README.md): the model's conditions of thesis §3.4
// (Theorems 1-3 for every label and pair of the model; the built-in condition "thesis",
// checker/smt/condition_registry.hpp) validated against the DPO semantics on a bounded family of
// rules and maps (checker/smt/condition_validation.hpp, consistency semantics).
#pragma once
#include <gtest/gtest.h>

#include <cstdio>

#include "checker/smt/condition_registry.hpp"
#include "checker/smt/condition_validation.hpp"
#include "checker/smt/symbolic_validation.hpp"
#include "checker/smt/validation_format.hpp"

namespace gmr::proofs {

// "For every rule over at most max_nodes nodes with arcs on `labels`, and every map of the model
// with at most `bound` darts: the rule satisfies the conditions iff every match glues and yields a
// map" (rules matching no map within the bound excluded). Fails with the smallest counterexample.
inline smt::ValidationReport prove_conditions(int n, MapKind kind, std::vector<int> labels,
                                              int max_nodes, unsigned bound,
                                              smt::Engine engine = smt::Engine::Smt) {
  const smt::BuiltinCondition* c = smt::find_builtin_condition("thesis");
  const smt::ValidationOptions o{.n = n,
                                 .kind = kind,
                                 .labels = std::move(labels),
                                 .max_nodes = max_nodes,
                                 .bound = bound,
                                 .engine = engine};
  const smt::ValidationReport r = smt::validate_condition(
      c->name,
      [&](const std::vector<rewrite::Rule>& rules) {
        std::vector<bool> out;
        for (const auto& x : rules) out.push_back(c->holds(x));
        return out;
      },
      o);
  std::printf("%s", smt::to_text(r).c_str());
  EXPECT_EQ(r.checked, r.rules);
  EXPECT_TRUE(r.sound()) << "sufficiency fails:\n" << smt::to_text(r);
  EXPECT_TRUE(r.complete()) << "necessity fails:\n" << smt::to_text(r);
  ::testing::Test::RecordProperty("seconds", std::to_string(r.seconds));
  return r;
}

// The same statement for the whole family at once, with the rule symbolic too
// (checker/smt/symbolic_validation.hpp): Theorems 1 and 2 as formulas, Theorem 3 (models with
// cycle pairs) through the concrete cycle checker's lemmas.
inline smt::SymbolicReport prove_conditions_symbolic(int n, MapKind kind, std::vector<int> labels,
                                                     int max_nodes, unsigned bound,
                                                     const std::string& condition = "thesis") {
  const smt::ValidationOptions o{
      .n = n, .kind = kind, .labels = std::move(labels), .max_nodes = max_nodes, .bound = bound};
  const smt::SymbolicReport r = smt::validate_symbolic(condition, o);
  std::printf("%s", smt::to_text(r).c_str());
  EXPECT_TRUE(r.sound()) << "sufficiency fails:\n" << smt::to_text(r);
  EXPECT_TRUE(r.complete()) << "necessity fails:\n" << smt::to_text(r);
  ::testing::Test::RecordProperty("seconds", std::to_string(r.sound_seconds + r.complete_seconds));
  return r;
}

}  // namespace gmr::proofs
