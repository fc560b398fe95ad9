// Properties of concrete DPO rules and of the concrete-rule checker, on random rules
// (proptests/rule_cases.hpp) and random maps (proptests/generators.hpp):
//  * soundness, by random testing: if check_rule accepts a rule, every direct derivation through
//    a match satisfying the gluing condition, on random maps of the rule's model, yields a map of
//    the model (Def. 32 constraints of H);
//  * completeness, by the enumeration engine: if check_rule rejects a rule that applies somewhere
//    on the exhaustive family of maps with <= 4 darts, some application there breaks the model
//    (semantic_verdict finds the witness);
//  * rules consistent by construction (component replacement, instances of accepted library
//    schemes) are accepted;
//  * the two DPO constructions (categorical and in place) agree on every application, on D-graphs
//    and on maps.
#include <gtest/gtest.h>

#include "checker/check_format.hpp"
#include "checker/rule_check.hpp"
#include "checker/semantic.hpp"
#include "model/core/error.hpp"
#include "model/core/signature.hpp"
#include "model/graph/constraints.hpp"
#include "model/graph/dgraph.hpp"
#include "model/rewrite/dpo.hpp"
#include "model/rewrite/match.hpp"
#include "proptests/generators.hpp"
#include "proptests/harness.hpp"
#include "proptests/rule_cases.hpp"

using namespace gmr;
using namespace gmr::graph;
using namespace gmr::rewrite;
using namespace gmr::checker;
using namespace gmr::prop;

namespace {

// A random map of the rule's model (same dimension and kind): half of the time from the random
// generators, half of the time the first map of the exhaustive small family (maps of <= 4 darts,
// from a random start) on which L has a match — random rules rarely match random maps.
Map random_map_for(const Rule& r) {
  if (*rc::gen::arbitrary<bool>() && r.dimension() <= 2) {
    const MapFamily& fam = small_maps(r.dimension(), r.kind());
    const size_t start = *rc::gen::inRange<size_t>(0, fam.maps.size());
    for (size_t k = 0; k < fam.maps.size(); ++k) {
      const size_t m = (start + k) % fam.maps.size();
      if (!find_matches(r.left(), fam.graphs[m], 1).empty()) return fam.maps[m];
    }
  }
  if (r.kind() == MapKind::OMap) return (*gen_omap_case_of_dim(r.dimension(), 4)).build();
  return (*gen_map_case_of_dim(r.dimension(), 4)).build();
}

// Every match (up to `limit`) of L in G satisfying the gluing condition.
std::vector<Match> applicable_matches(const Rule& r, const DGraph& G, size_t limit) {
  std::vector<Match> out;
  for_each_match(r.left(), G, [&](const Match& m) {
    if (satisfies_gluing(r, G, m)) out.push_back(m);
    return out.size() < limit;
  });
  return out;
}

}  // namespace

TEST(ConcreteProps, AcceptedRulesPreserveTheModelOnRandomMaps) {
  const auto gen = rc::gen::oneOf(gen_arbitrary_rule_case(), gen_consistent_rule_case());
  EXPECT_TRUE(check_property<RuleCase>("concrete_accepted_preserve", gen, [](const RuleCase& c) {
    const Rule r = c.build();
    const bool accepted = check_rule(r).ok();
    RC_TAG(accepted ? "accepted" : "rejected");
    if (!accepted) return;
    size_t applied = 0;
    for (int k = 0; k < 4; ++k) {
      const Map g = random_map_for(r);
      const DGraph G = to_dgraph(g);
      for (const Match& m : applicable_matches(r, G, 8)) {
        const Derivation d = derive(r, G, m);
        const auto broken = check_map_constraints(d.H, r.dimension(), r.kind());
        if (!broken.empty()) RC_LOG() << "map " << describe_counterexample(g) << "\n";
        RC_ASSERT(broken.empty());
        ++applied;
      }
    }
    RC_CLASSIFY(applied > 0, "applied on random maps");
  }));
}

TEST(ConcreteProps, RejectedRulesBreakTheModelOnSmallMaps) {
  EXPECT_TRUE(check_property<RuleCase>(
      "concrete_rejected_witness", gen_arbitrary_rule_case(), [](const RuleCase& c) {
        const Rule r = c.build();
        const CheckReport rep = check_rule(r);
        RC_TAG(rep.ok() ? "accepted" : "rejected");
        const SemanticVerdict v = semantic_verdict(r, small_maps(r.dimension(), r.kind()));
        RC_CLASSIFY(!v.applicable(), "not applicable within 4 darts");
        if (!v.applicable())
          return;  // vacuous within the bound (see checker/tests/equivalence_test.cpp)
        if (rep.ok() != v.preserves) RC_LOG() << "checker: " << to_text(rep) << "\n";
        RC_ASSERT(rep.ok() == v.preserves);  // both directions on the exhaustive bound
      }));
}

TEST(ConcreteProps, ConsistentByConstructionIsAccepted) {
  EXPECT_TRUE(check_property<RuleCase>("concrete_valid_accepted", gen_consistent_rule_case(),
                                       [](const RuleCase& c) {
                                         const Rule r = c.build();
                                         const CheckReport rep = check_rule(r);
                                         if (!rep.ok()) RC_LOG() << to_text(rep) << "\n";
                                         RC_ASSERT(rep.ok());
                                       }));
}

TEST(ConcreteProps, TwoDpoConstructionsAgree) {
  const auto gen = rc::gen::oneOf(gen_arbitrary_rule_case(), gen_consistent_rule_case());
  EXPECT_TRUE(check_property<RuleCase>("concrete_dpo_agree", gen, [](const RuleCase& c) {
    const Rule r = c.build();
    const Map g = random_map_for(r);
    const DGraph G = to_dgraph(g);
    const auto matches = applicable_matches(r, G, 6);
    RC_CLASSIFY(matches.empty(), "no applicable match");
    for (const Match& m : matches) {
      std::string why;
      const Derivation a = derive(r, G, m), b = derive(r, G, m, Construction::Rewriting);
      if (!same_derivation(a, b, &why)) RC_FAIL("categorical vs rewriting derivation: " + why);
      // On maps, when H is combinatorial (else both refuse).
      std::vector<Dart> dm;
      const auto darts = g.darts();
      for (Node v : m.node) dm.push_back(darts[v.index()]);
      bool ok1 = true, ok2 = true;
      MapDerivation h1, h2;
      try {
        h1 = apply(r, g, dm, Construction::Categorical);
      } catch (const Error&) {
        ok1 = false;
      }
      try {
        h2 = apply(r, g, dm, Construction::Rewriting);
      } catch (const Error&) {
        ok2 = false;
      }
      RC_ASSERT(ok1 == ok2);
      if (ok1) {
        RC_ASSERT(is_isomorphic(h1.H, h2.H));
        RC_ASSERT(h1.H.size() == h2.H.size());
      }
    }
  }));
}
