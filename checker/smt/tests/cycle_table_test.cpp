// The table of C_r on component patterns (checker/smt/cycle_table.hpp) and its lemmas in the
// symbolic engine (symbolic_cycle.hpp, table_lemmas): every component of a rule of the family that
// satisfies Theorems 1-2 is a pattern of the table, with the checker's verdict on the component;
// the lemmas fix ok on every component of a rule to that verdict; and the symbolic engine reaches
// the same verdicts with the table as with the lazily learnt lemmas alone.
#include "checker/smt/cycle_table.hpp"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <set>

#include "checker/rule_check.hpp"
#include "checker/smt/cycle_components.hpp"
#include "checker/smt/rule_space.hpp"
#include "checker/smt/symbolic_cycle.hpp"

using namespace gmr;
using namespace gmr::smt;
using rewrite::Rule;

namespace {
const MapSpec kTableSpec{2, MapKind::GMap};

std::pair<std::vector<int>, std::vector<uint64_t>> table_pattern_of(
    const Rule& r, std::vector<std::string> nodes, const std::vector<int>& labels) {
  const ComponentPattern p = component_pattern(r, std::move(nodes), labels);
  return {p.status, p.arcs};
}

bool theorems12_on_labels(const Rule& r, const std::vector<int>& labels) {
  std::vector<checker::Diagnostic> d;
  for (int i : labels)
    if (!checker::check_incident_arcs(r, i, d) || !checker::check_non_orientation(r, i, d))
      return false;
  return true;
}
}  // namespace

// Every rule of the 2-G-map family of at most 2 nodes (labels 0, 2) that satisfies Theorems 1-2:
// each component is a pattern of the table, with the verdict of the checker on the component; in
// each reading. Every pattern of the table is met (each is itself a rule of the family).
TEST(CycleTable, EveryComponentIsTabulatedWithTheCheckersVerdict) {
  for (CycleReading reading :
       {CycleReading::ModelCompletion, CycleReading::IjCompletion, CycleReading::AsWritten}) {
    const CycleTable table = cycle_table(kTableSpec, {0, 1, 2}, 2, ThesisParts{}, reading);
    EXPECT_EQ(table.labels, (std::vector<int>{0, 2}));
    std::map<std::pair<std::vector<int>, std::vector<uint64_t>>, bool> verdict;
    for (const auto& p : table.patterns)
      EXPECT_TRUE(verdict.emplace(std::pair{p.status, p.arcs}, p.holds).second);
    std::set<std::pair<std::vector<int>, std::vector<uint64_t>>> met;
    size_t rules = 0;
    for_each_rule(2, MapKind::GMap, 2, {0, 2}, [&](size_t, const Rule& r) {
      if (!theorems12_on_labels(r, {0, 2})) return true;
      ++rules;
      for (const auto& k : rule_components(r, {0, 2})) {
        const auto key = table_pattern_of(r, k, {0, 2});
        const auto it = verdict.find(key);
        EXPECT_NE(it, verdict.end()) << rule_text(r);
        if (it == verdict.end()) return false;
        EXPECT_EQ(it->second, cycle_condition(restrict_rule(r, k, {0, 2}), reading))
            << rule_text(r);
        met.insert(key);
      }
      return true;
    });
    EXPECT_EQ(met.size(), verdict.size());
    EXPECT_GT(rules, 0u);
  }
  // The sizes: 6 one-node and 81 connected two-node patterns (labels 0, 2); 3 labels' worth of arcs
  // in the family change nothing (label 1 is no cycle label).
  const CycleTable t =
      cycle_table(kTableSpec, {0, 2}, 2, ThesisParts{}, CycleReading::ModelCompletion);
  EXPECT_EQ(t.patterns.size(), 87u);
  // Without arcs on label 2, only patterns without added nodes and without 2-arcs remain.
  const CycleTable t0 =
      cycle_table(kTableSpec, {0, 1}, 2, ThesisParts{}, CycleReading::ModelCompletion);
  EXPECT_EQ(t0.labels, (std::vector<int>{0}));
  for (const auto& p : t0.patterns)
    for (int s : p.status) EXPECT_NE(s, 2);
}

// The cubes of the 3-node table: every failing pattern lies in some failing cube, no holding one in
// any (far fewer cubes than failing patterns), and the converse for the holding cubes.
TEST(CycleTable, CubesHoldEveryFailingPatternAndNoHoldingOne) {
  const CycleTable table =
      cycle_table(kTableSpec, {0, 1, 2}, 3, ThesisParts{}, CycleReading::ModelCompletion);
  const std::vector<PatternCube> cubes = failing_cubes(table);
  size_t failing = 0;
  for (const ComponentPattern& p : table.patterns) {
    const PatternBits b = pattern_bits(p, table.labels.size());
    size_t in = 0;
    for (const PatternCube& c : cubes)
      in += c.nodes == p.nodes() && (b[0] & c.care[0]) == c.value[0] &&
            (b[1] & c.care[1]) == c.value[1];
    failing += !p.holds;
    if (p.holds)
      EXPECT_EQ(in, 0u);
    else
      EXPECT_GT(in, 0u);
  }
  EXPECT_EQ(table.patterns.size(), 2198u);  // 6 + 81 + 2111 connected patterns
  EXPECT_EQ(failing, 1166u);
  EXPECT_LT(cubes.size(), failing / 4);
  // The holding cubes likewise: every holding pattern in one, no failing one in any.
  const std::vector<PatternCube> holding = verdict_cubes(table, true);
  for (const ComponentPattern& p : table.patterns) {
    const PatternBits b = pattern_bits(p, table.labels.size());
    size_t in = 0;
    for (const PatternCube& c : holding)
      in += c.nodes == p.nodes() && (b[0] & c.care[0]) == c.value[0] &&
            (b[1] & c.care[1]) == c.value[1];
    if (p.holds)
      EXPECT_GT(in, 0u);
    else
      EXPECT_EQ(in, 0u);
  }
  EXPECT_LT(holding.size(), table.patterns.size() - failing);
}

// The table lemmas (exact) and the cube lemmas (failing ones unguarded, as the soundness query has
// them; both verdicts under a guard, as the completeness query) on 3 slots fix ok on every
// component of a rule to the checker's verdict: rules built as disjoint unions of tabulated
// patterns (one of 3 nodes, 2 + 1, 1 + 1 + 1 nodes), drawn at random, renamed into the family's
// status order.
TEST(CycleTable, LemmasFixOkOnEveryComponent) {
  const CycleTable table =
      cycle_table(kTableSpec, {0, 1, 2}, 3, ThesisParts{}, CycleReading::ModelCompletion);
  z3::context ctx;
  const SymbolicRule sym(ctx, kTableSpec, 3, {0, 1, 2});
  const SymbolicCycle cyc(sym, {0, 2});
  z3::solver s(ctx), cubed(ctx);
  s.add(sym.family());
  s.add(cyc.table_lemmas(table));
  cubed.add(sym.family());
  cubed.add(cyc.cube_lemmas(table, failing_cubes(table), ctx.bool_val(true)));
  // Both verdicts' cubes under a guard literal (the completeness query's form).
  z3::solver both(ctx);
  const z3::expr guard = ctx.bool_const("guard");
  both.add(sym.family());
  both.add(cyc.cube_lemmas(table, verdict_cubes(table, false), guard));
  both.add(cyc.cube_lemmas(table, verdict_cubes(table, true), guard));
  std::vector<std::vector<const ComponentPattern*>> by_size(4);
  for (const auto& p : table.patterns) by_size[p.nodes()].push_back(&p);
  std::mt19937_64 rng(11);
  size_t checked = 0, failing = 0;
  for (const std::vector<size_t>& sizes : std::vector<std::vector<size_t>>{{3}, {2, 1}, {1, 1, 1}})
    for (int t = 0; t < 30; ++t) {
      // The union: each part's nodes named after the next letters, then renamed into status order.
      graph::DGraph L, R;
      char next = 'a';
      for (size_t k : sizes) {
        const ComponentPattern& p = *by_size[k][rng() % by_size[k].size()];
        std::vector<graph::Node> lv(k, graph::kNoNode), rv(k, graph::kNoNode);
        for (size_t x = 0; x < k; ++x) {
          const std::string name(1, next++);
          if (p.status[x] != 2) lv[x] = L.add_node(name);
          if (p.status[x] != 1) rv[x] = R.add_node(name);
        }
        for (size_t l = 0; l < table.labels.size(); ++l)
          for (size_t x = 0; x < k; ++x)
            for (size_t y = 0; y < k; ++y) {
              if (p.arc(false, l, table.labels.size(), x, y))
                L.add_arc(lv[x], lv[y], table.labels[l]);
              if (p.arc(true, l, table.labels.size(), x, y))
                R.add_arc(rv[x], rv[y], table.labels[l]);
            }
      }
      Rule u(std::move(L), std::move(R), 2, MapKind::GMap, "union");
      // Status order along a, b, c, d: sort the names by status.
      std::vector<std::pair<int, std::string>> nodes;
      for (graph::Node v : u.left().nodes())
        nodes.emplace_back(u.right_of(v) ? 0 : 1, u.left().name(v));
      for (graph::Node w : u.added_nodes()) nodes.emplace_back(2, u.right().name(w));
      std::stable_sort(nodes.begin(), nodes.end(),
                       [](const auto& x, const auto& y) { return x.first < y.first; });
      std::map<std::string, std::string> to;
      for (size_t k = 0; k < nodes.size(); ++k)
        to[nodes[k].second] = std::string(1, static_cast<char>('a' + k));
      auto side = [&](const graph::DGraph& g) {
        std::vector<graph::Node> order(g.nodes().begin(), g.nodes().end());
        std::sort(order.begin(), order.end(),
                  [&](auto x, auto y) { return to[g.name(x)] < to[g.name(y)]; });
        graph::DGraph out;
        HandleVector<graph::Node, graph::Node> at(g.num_nodes());
        for (graph::Node v : order) at[v] = out.add_node(to[g.name(v)]);
        for (graph::ArcId a : g.arc_slots())
          if (g.arc_alive(a)) out.add_arc(at[g.arc(a).src], at[g.arc(a).tgt], g.arc(a).label);
        return out;
      };
      const Rule r(side(u.left()), side(u.right()), 2, MapKind::GMap, "union");
      ASSERT_TRUE(theorems12_on_labels(r, {0, 2})) << rule_text(r);
      const auto components = rule_components(r, {0, 2});
      EXPECT_EQ(components.size(), sizes.size()) << rule_text(r);
      for (const auto& k : components) {
        const bool verdict =
            cycle_condition(restrict_rule(r, k, {0, 2}), CycleReading::ModelCompletion);
        failing += !verdict;
        s.push();
        s.add(sym.describes(r));
        s.add(cyc.ok(cyc.mask_of(k)) != ctx.bool_val(verdict));
        EXPECT_EQ(s.check(), z3::unsat) << rule_text(r);
        s.pop();
        // The cubes: not ok on a failing component; nothing on a holding one.
        cubed.push();
        cubed.add(sym.describes(r));
        cubed.add(cyc.ok(cyc.mask_of(k)));
        EXPECT_EQ(cubed.check(), verdict ? z3::sat : z3::unsat) << rule_text(r);
        cubed.pop();
        // Both kinds, guarded: ok fixed to the verdict under the guard, free without it.
        both.push();
        both.add(sym.describes(r));
        both.add(cyc.ok(cyc.mask_of(k)) != ctx.bool_val(verdict));
        EXPECT_EQ(both.check(), z3::sat) << rule_text(r);
        both.add(guard);
        EXPECT_EQ(both.check(), z3::unsat) << rule_text(r);
        both.pop();
        ++checked;
      }
      // And the whole rule: C_r is the conjunction of its components' verdicts.
      EXPECT_EQ(cycle_condition(r, CycleReading::ModelCompletion),
                cycle_condition_by_components(r, CycleReading::ModelCompletion))
          << rule_text(r);
    }
  EXPECT_GT(failing, 0u);
  EXPECT_LT(failing, checked);
}
