// C_r by components in the symbolic engine (checker/smt/symbolic_cycle.hpp, cycle_components.hpp):
// the component formulas equal the components of the concrete rule, and a lemma learnt on one rule
// fixes `ok` on every placement of the component's pattern and on nothing else. (The
// decomposition itself is proved on every rule of at most 3 nodes:
// proofs/cycle_components_proof.cpp.)
#include "checker/smt/symbolic_cycle.hpp"

#include <gtest/gtest.h>

#include <random>

#include "checker/smt/cycle_components.hpp"
#include "checker/smt/rule_space.hpp"
#include "checker/smt/symbolic_validation.hpp"

using namespace gmr;
using namespace gmr::smt;
using rewrite::Rule;

namespace {
const MapSpec kSpec{2, MapKind::GMap};

// The rule as written with its nodes renamed by `perm` (node x -> perm[x]).
Rule renamed(const Rule& r, const std::string& perm) {
  auto side = [&](const graph::DGraph& g) {
    graph::DGraph out;
    HandleVector<graph::Node, graph::Node> to(g.num_nodes());
    for (graph::Node v : g.nodes()) to[v] = out.add_node(std::string(1, perm[g.name(v)[0] - 'a']));
    for (graph::ArcId a : g.arc_slots())
      if (g.arc_alive(a)) out.add_arc(to[g.arc(a).src], to[g.arc(a).tgt], g.arc(a).label);
    return out;
  };
  return Rule(side(r.left()), side(r.right()), r.dimension(), r.kind(), r.name());
}

// The rule renamed so that its nodes are in the family's status order along a, b, c, ...
// (preserved, deleted, added), as the symbolic rule's symmetry breaking wants them.
Rule in_family_order(const Rule& r) {
  std::vector<std::pair<int, std::string>> nodes;  // (status, name)
  for (graph::Node v : r.left().nodes())
    nodes.emplace_back(r.right_of(v) ? 0 : 1, r.left().name(v));
  for (graph::Node w : r.added_nodes()) nodes.emplace_back(2, r.right().name(w));
  std::stable_sort(nodes.begin(), nodes.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  std::string perm(8, '?');
  for (size_t k = 0; k < nodes.size(); ++k)
    perm[nodes[k].second[0] - 'a'] = static_cast<char>('a' + k);
  return renamed(r, perm);
}
}  // namespace

// On every rule of the 2-G-map family of at most 2 nodes (labels 0, 2) and on 300 random rules of
// 3 and 4 nodes (labels 0, 1, 2): component(S) holds exactly for the node sets of the rule's
// components under the 0- and 2-arcs.
TEST(SymbolicCycle, ComponentFormulasAreTheRulesComponents) {
  for (int slots : {2, 3, 4}) {
    z3::context ctx;
    const SymbolicRule sym(ctx, kSpec, slots, {0, 1, 2});
    const SymbolicCycle cyc(sym, {0, 2});
    z3::solver s(ctx);
    s.add(sym.family());
    size_t rules = 0, split = 0;
    auto check = [&](const Rule& r) {
      s.push();
      s.add(sym.describes(r));
      EXPECT_EQ(s.check(), z3::sat) << rule_text(r);
      const z3::model m = s.get_model();
      std::vector<unsigned> expected;
      for (const auto& k : rule_components(r, {0, 2})) expected.push_back(cyc.mask_of(k));
      split += expected.size() > 1;
      for (unsigned mask = 1; mask < (1u << slots); ++mask) {
        const bool is = std::find(expected.begin(), expected.end(), mask) != expected.end();
        EXPECT_EQ(m.eval(cyc.component(mask), true).is_true(), is)
            << "mask " << mask << " on " << rule_text(r);
      }
      s.pop();
      ++rules;
      return !::testing::Test::HasFailure();
    };
    if (slots == 2) {
      for_each_rule(2, MapKind::GMap, 2, {0, 2}, [&](size_t, const Rule& r) { return check(r); });
    } else {
      std::mt19937_64 rng(static_cast<unsigned>(slots));
      for (int t = 0;
           t < 300 &&
           check(in_family_order(random_rule(rng, 2, MapKind::GMap, slots, {0, 1, 2}, "random")));
           ++t) {
      }
    }
    EXPECT_GT(split, 0u);
    EXPECT_GT(rules, 0u);
  }
}

// A lemma learnt on a component of one rule (a random 4-node rule with a component of at least
// two nodes) fixes ok on every renaming of the rule that keeps the family's status order (the
// component then sits on other slots), and leaves ok free once an arc of the component is removed.
TEST(SymbolicCycle, LemmaCoversEveryPlacementAndNoOtherPattern) {
  z3::context ctx;
  const SymbolicRule sym(ctx, kSpec, 4, {0, 1, 2});
  const SymbolicCycle cyc(sym, {0, 2});
  std::mt19937_64 rng(7);
  size_t lemmas = 0, placements = 0, others = 0;
  for (int t = 0; t < 400 && lemmas < 40; ++t) {
    const Rule r = in_family_order(random_rule(rng, 2, MapKind::GMap, 4, {0, 2}, "random"));
    const auto components = rule_components(r, {0, 2});
    const auto big = std::find_if(components.begin(), components.end(),
                                  [](const auto& k) { return k.size() >= 2; });
    if (big == components.end()) continue;
    z3::solver s(ctx);
    s.add(sym.family());
    s.push();
    s.add(sym.describes(r));
    ASSERT_EQ(s.check(), z3::sat);
    const z3::model m = s.get_model();
    const unsigned mask = cyc.mask_of(*big);
    const bool verdict =
        cycle_condition(restrict_rule(r, *big, {0, 2}), CycleReading::ModelCompletion);
    s.pop();
    s.add(cyc.lemma(m, mask, verdict));
    ++lemmas;
    // Every renaming in the family: ok of the component's new slots is the verdict.
    std::string perm = "abcd";
    do {
      const Rule p = renamed(r, perm);
      s.push();
      try {
        s.add(sym.describes(p));
      } catch (...) {
        s.pop();
        continue;
      }
      if (s.check() == z3::sat) {  // the renaming keeps the status order
        std::vector<std::string> moved;
        for (const auto& name : *big) moved.push_back(std::string(1, perm[name[0] - 'a']));
        s.add(cyc.ok(cyc.mask_of(moved)) != ctx.bool_val(verdict));
        EXPECT_EQ(s.check(), z3::unsat) << rule_text(p);
        ++placements;
      }
      s.pop();
    } while (std::next_permutation(perm.begin(), perm.end()));
    // Another pattern on the same slots: one L arc of the component's first node removed (one arc
    // fewer: no placement of the pattern, nor of the pattern with 0 and 2 swapped).
    graph::DGraph L = r.left();
    const auto v = L.find(big->front());
    if (!v) continue;
    bool removed = false;
    for (graph::ArcId a(0); a.index() < L.num_arc_slots() && !removed; ++a)
      if (L.arc_alive(a) && L.arc(a).src == *v) {
        L.remove_arc(a);
        removed = true;
      }
    if (!removed) continue;
    const Rule other(std::move(L), r.right(), 2, MapKind::GMap, "other");
    {
      s.push();
      s.add(sym.describes(other));
      if (s.check() == z3::sat) {
        s.add(cyc.ok(mask) != ctx.bool_val(verdict));
        EXPECT_EQ(s.check(), z3::sat)
            << "the lemma of " << rule_text(r) << " constrains " << rule_text(other);
        ++others;
      }
      s.pop();
    }
  }
  EXPECT_GE(lemmas, 20u);
  EXPECT_GT(placements, lemmas);
  EXPECT_GT(others, 0u);
}
