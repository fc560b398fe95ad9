// Bounded proof of the decomposition of C_r by components (checker/smt/cycle_components.hpp;
// proofs/README.md, "C_r by components"), on which the symbolic engine's cycle lemmas rest: for
// EVERY rule of the 2-G-map family of at most `nodes` nodes with arcs on the cycle labels 0, 2
// (C_r reads no other label) that satisfies w-I_r on 0 and 2, in each reading of C_r,
//   (1) C_r of the rule = AND over its components of C_r of the component, and
//   (2) C_r is the same on every renaming and reordering of the rule's nodes and arcs
//       (the lemmas place a component's pattern on any slots), and with the labels 0 and 2
//       swapped (the lemmas place the swapped pattern too), and
//   (3) every component is a pattern of the symbolic engine's table (cycle_table.hpp) with the
//       checker's verdict on it (the table then decides C_r of every rule of the family).
// Without w-I_r, (1) fails on some rule (looked for on one rule in 64 of those): the guard of the
// decomposition is needed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>

#include "checker/rule_check.hpp"
#include "checker/smt/cycle_components.hpp"
#include "checker/smt/cycle_table.hpp"
#include "checker/smt/rule_space.hpp"

using namespace gmr;
using namespace gmr::smt;
using graph::ArcId;
using graph::DGraph;
using graph::Node;
using rewrite::Rule;

namespace {
// The rule with its node names permuted (name x -> perm[x], names a, b, c, ...), nodes added in
// the order of their new names and arcs in the reverse order.
Rule renamed(const Rule& r, const std::string& perm) {
  auto rename = [&](const std::string& name) { return std::string(1, perm[name[0] - 'a']); };
  auto side = [&](const DGraph& g) {
    std::vector<Node> order(g.nodes().begin(), g.nodes().end());
    std::sort(order.begin(), order.end(),
              [&](Node x, Node y) { return rename(g.name(x)) < rename(g.name(y)); });
    DGraph out;
    HandleVector<Node, Node> to(g.num_nodes());
    for (Node v : order) to[v] = out.add_node(rename(g.name(v)));
    for (auto k = static_cast<uint32_t>(g.num_arc_slots()); k-- > 0;)
      if (const ArcId a(k); g.arc_alive(a))
        out.add_arc(to[g.arc(a).src], to[g.arc(a).tgt], g.arc(a).label);
    return out;
  };
  return Rule(side(r.left()), side(r.right()), r.dimension(), r.kind(), r.name());
}

// The rule with the labels 0 and 2 swapped.
Rule swapped_02(const Rule& r) {
  auto side = [&](const DGraph& g) {
    DGraph out;
    for (Node v : g.nodes()) out.add_node(g.name(v));
    for (ArcId a : g.arc_slots())
      if (g.arc_alive(a))
        out.add_arc(g.arc(a).src, g.arc(a).tgt, g.arc(a).label == 1 ? 1 : 2 - g.arc(a).label);
    return out;
  };
  return Rule(side(r.left()), side(r.right()), r.dimension(), r.kind(), r.name());
}

size_t node_count(const Rule& r) { return r.left().num_nodes() + r.added_nodes().size(); }

void prove_decomposition(int nodes) {
  const std::vector<std::pair<const char*, CycleReading>> readings = {
      {"model completion", CycleReading::ModelCompletion},
      {"ij-completion", CycleReading::IjCompletion},
      {"as written", CycleReading::AsWritten}};
  size_t rules = 0, guarded = 0, split = 0, split_mixed = 0, unguarded_differ = 0, looked_up = 0;
  // (3) Every component of a rule with w-I_r is a pattern of the symbolic engine's table
  // (cycle_table.hpp, built here with w-I_r only), with the checker's verdict on the component.
  std::vector<std::map<std::pair<std::vector<int>, std::vector<uint64_t>>, bool>> table(
      readings.size());
  for (size_t k = 0; k < readings.size(); ++k)
    for (const auto& p :
         cycle_table(MapSpec{2, MapKind::GMap}, {0, 2}, nodes,
                     ThesisParts{.dangling = false, .orientation = false}, readings[k].second)
             .patterns)
      table[k].emplace(std::pair{p.status, p.arcs}, p.holds);
  for_each_rule(2, MapKind::GMap, nodes, {0, 2}, [&](size_t index, const Rule& r) {
    ++rules;
    std::vector<checker::Diagnostic> d;
    const bool w_ir =
        checker::check_weak_incident_arcs(r, 0, d) && checker::check_weak_incident_arcs(r, 2, d);
    if (!w_ir && index % 64 != 0) return true;  // the guard's necessity: one rule in 64 is enough
    const auto components = rule_components(r, {0, 2});
    for (size_t ri = 0; ri < readings.size(); ++ri) {
      const auto& [name, reading] = readings[ri];
      const bool whole = cycle_condition(r, reading);
      const bool by_components = cycle_condition_by_components(r, reading);
      if (!w_ir) {
        if (whole != by_components) ++unguarded_differ;
        continue;
      }
      EXPECT_EQ(whole, by_components) << name << " on " << rule_text(r);
      size_t failing = 0;
      for (const auto& k : components) {
        const bool verdict =
            components.size() == 1 ? whole : cycle_condition(restrict_rule(r, k, {0, 2}), reading);
        failing += !verdict;
        const ComponentPattern p = component_pattern(r, k, {0, 2});
        const auto it = table[ri].find(std::pair{p.status, p.arcs});
        ++looked_up;
        if (it == table[ri].end()) {
          ADD_FAILURE() << name << ": a component of " << rule_text(r) << " is not in the table";
          break;
        }
        EXPECT_EQ(it->second, verdict) << name << " on a component of " << rule_text(r);
      }
      if (components.size() > 1) {
        ++split;
        if (failing > 0 && failing < components.size()) ++split_mixed;
      }
      EXPECT_EQ(cycle_condition(swapped_02(r), reading), whole)
          << name << " on " << rule_text(r) << ", 0 and 2 swapped";
      std::string perm = std::string("abcd").substr(0, node_count(r));
      while (std::next_permutation(perm.begin(), perm.end()))
        EXPECT_EQ(cycle_condition(renamed(r, perm), reading), whole)
            << name << " on " << rule_text(r) << ", renamed " << perm;
    }
    guarded += w_ir;
    return !::testing::Test::HasFailure();
  });
  size_t family = 0;
  for (int m = 1; m <= nodes; ++m) family += count_rules(m, 2);
  std::printf(
      "%zu rules, %zu with w-I_r on 0 and 2; with w-I_r: %zu verdicts on several components, %zu "
      "of them with "
      "failing and holding components; without w-I_r (one rule in 64): %zu verdicts differ\n",
      rules, guarded, split, split_mixed, unguarded_differ);
  EXPECT_EQ(rules, family);
  EXPECT_GT(looked_up, 0u);
  EXPECT_GT(split_mixed, 0u);       // the decomposition is exercised where it matters
  EXPECT_GT(unguarded_differ, 0u);  // and the guard is needed
}
}  // namespace

// Every rule of at most 3 nodes (1,466,908 rules).
TEST(Proof, CycleByComponents_2GMaps_Labels02_Nodes3_EveryRule) { prove_decomposition(3); }

// Every 2-G-map rule of 4 nodes with w-I_r on 0 and 2 (labels 0, 2) that has several components,
// up to the order of its nodes: the disjoint unions of the table's connected patterns of 3 + 1,
// 2 + 2, 2 + 1 + 1 and 1 + 1 + 1 + 1 nodes. C_r of the union (the checker) is the conjunction of
// the table's verdicts on its parts, in each reading: the decomposition on which the 4-node
// symbolic proof rests (a 4-node component is itself a tabulated pattern).
TEST(Proof, CycleByComponents_2GMaps_Labels02_Nodes4_EveryRuleOfSeveralComponents) {
  const std::vector<std::pair<const char*, CycleReading>> readings = {
      {"model completion", CycleReading::ModelCompletion},
      {"ij-completion", CycleReading::IjCompletion},
      {"as written", CycleReading::AsWritten}};
  const std::vector<int> labels{0, 2};
  size_t unions = 0, mixed = 0;
  for (const auto& [name, reading] : readings) {
    const CycleTable table =
        cycle_table(MapSpec{2, MapKind::GMap}, labels, 3,
                    ThesisParts{.dangling = false, .orientation = false}, reading);
    std::vector<std::vector<const ComponentPattern*>> by_size(4);
    for (const auto& p : table.patterns) by_size[p.nodes()].push_back(&p);
    for (const std::vector<size_t>& sizes :
         std::vector<std::vector<size_t>>{{3, 1}, {2, 2}, {2, 1, 1}, {1, 1, 1, 1}}) {
      std::vector<size_t> choice(sizes.size(), 0);
      while (true) {
        DGraph L, R;
        char next = 'a';
        bool all = true, some = false;
        for (size_t part = 0; part < sizes.size(); ++part) {
          const ComponentPattern& p = *by_size[sizes[part]][choice[part]];
          all = all && p.holds;
          some = some || p.holds;
          const size_t k = p.nodes();
          std::vector<Node> lv(k), rv(k);
          for (size_t x = 0; x < k; ++x) {
            const std::string node(1, next++);
            if (p.status[x] != 2) lv[x] = L.add_node(node);
            if (p.status[x] != 1) rv[x] = R.add_node(node);
          }
          for (size_t l = 0; l < labels.size(); ++l)
            for (size_t x = 0; x < k; ++x)
              for (size_t y = 0; y < k; ++y) {
                if (p.arc(false, l, labels.size(), x, y)) L.add_arc(lv[x], lv[y], labels[l]);
                if (p.arc(true, l, labels.size(), x, y)) R.add_arc(rv[x], rv[y], labels[l]);
              }
        }
        const Rule u(std::move(L), std::move(R), 2, MapKind::GMap, "union");
        ++unions;
        mixed += some && !all;
        EXPECT_EQ(cycle_condition(u, reading), all) << name << " on " << rule_text(u);
        if (::testing::Test::HasFailure()) return;
        size_t part = 0;
        while (part < sizes.size() && ++choice[part] == by_size[sizes[part]].size())
          choice[part++] = 0;
        if (part == sizes.size()) break;
      }
    }
  }
  std::printf(
      "%zu unions of several components (all readings), %zu with failing and holding parts\n",
      unions, mixed);
  EXPECT_GT(mixed, 0u);
}
