#include "checker/smt/cycle_table.hpp"

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <string>

#include "checker/rule_check.hpp"
#include "checker/smt/cycle_components.hpp"

namespace gmr::smt {
using graph::DGraph;
using graph::Node;
using rewrite::Rule;

namespace {
// Partial injections on m nodes as arc bit sets (bit x * k + y, k nodes in all; `at` lists the
// pattern nodes of this side).
std::vector<uint64_t> partial_injections(const std::vector<size_t>& at, size_t k) {
  std::vector<uint64_t> out;
  std::vector<bool> used(at.size(), false);
  std::function<void(size_t, uint64_t)> rec = [&](size_t s, uint64_t bits) {
    if (s == at.size()) {
      out.push_back(bits);
      return;
    }
    rec(s + 1, bits);
    for (size_t t = 0; t < at.size(); ++t) {
      if (used[t]) continue;
      used[t] = true;
      rec(s + 1, bits | (uint64_t{1} << (at[s] * k + at[t])));
      used[t] = false;
    }
  };
  rec(0, 0);
  return out;
}

// The pattern as a rule (nodes a, b, c, ... in order; arcs on `labels`).
Rule pattern_rule(const MapSpec& spec, const std::vector<int>& status,
                  const std::vector<int>& labels, const std::vector<uint64_t>& arcs) {
  const size_t k = status.size();
  DGraph L, R;
  std::vector<Node> left(k, graph::kNoNode), right(k, graph::kNoNode);
  for (size_t x = 0; x < k; ++x) {
    const std::string name(1, static_cast<char>('a' + x));
    if (status[x] != 2) left[x] = L.add_node(name);
    if (status[x] != 1) right[x] = R.add_node(name);
  }
  for (size_t l = 0; l < labels.size(); ++l)
    for (size_t x = 0; x < k; ++x)
      for (size_t y = 0; y < k; ++y) {
        const uint64_t bit = uint64_t{1} << (x * k + y);
        if (arcs[l] & bit) L.add_arc(left[x], left[y], labels[l]);
        if (arcs[labels.size() + l] & bit) R.add_arc(right[x], right[y], labels[l]);
      }
  return Rule(std::move(L), std::move(R), spec.n, spec.kind, "pattern");
}

// The parts of Theorems 1-2 in the condition, on label i (checker/rule_check.hpp).
bool theorems12_on(const Rule& r, int i, const MapSpec& spec, const ThesisParts& parts) {
  std::vector<checker::Diagnostic> d;
  const bool incident = parts.dangling ? checker::check_incident_arcs(r, i, d)
                                       : checker::check_weak_incident_arcs(r, i, d);
  if (!incident) return false;
  return !parts.orientation || !spec.is_involutive_dim(i) ||
         checker::check_non_orientation(r, i, d);
}
}  // namespace

CycleTable cycle_table(const MapSpec& spec, const std::vector<int>& rule_labels, int max_nodes,
                       const ThesisParts& parts, CycleReading reading) {
  if (max_nodes > 8) throw std::logic_error("cycle_table: at most 8 nodes (64 arc bits)");
  CycleTable table;
  table.max_nodes = max_nodes;
  const std::vector<int> all = cycle_labels(spec);
  for (int l : all)
    if (std::find(rule_labels.begin(), rule_labels.end(), l) != rule_labels.end())
      table.labels.push_back(l);
  const size_t nl = table.labels.size();
  for (int k = 1; k <= max_nodes; ++k) {
    std::vector<int> status(static_cast<size_t>(k));
    std::function<void(size_t, int)> tuples = [&](size_t x, int min) {
      if (x < status.size()) {
        for (int s = min; s < 3; ++s) {
          status[x] = s;
          tuples(x + 1, s);
        }
        return;
      }
      std::vector<size_t> ln, rn;
      for (size_t y = 0; y < status.size(); ++y) {
        if (status[y] != 2) ln.push_back(y);
        if (status[y] != 1) rn.push_back(y);
      }
      const auto pl = partial_injections(ln, status.size()),
                 pr = partial_injections(rn, status.size());
      // A cycle label without arcs in the family must hold with none (an added node fails w-I_r).
      const Rule bare = pattern_rule(spec, status, table.labels, std::vector<uint64_t>(2 * nl, 0));
      for (int l : all)
        if (std::find(table.labels.begin(), table.labels.end(), l) == table.labels.end() &&
            !theorems12_on(bare, l, spec, parts))
          return;
      // Per cycle label, the (L, R) arc sets satisfying Theorems 1-2 on that label (each
      // condition reads one label).
      std::vector<std::vector<std::pair<uint64_t, uint64_t>>> per_label(nl);
      for (size_t l = 0; l < nl; ++l)
        for (uint64_t a : pl)
          for (uint64_t b : pr) {
            std::vector<uint64_t> arcs(2 * nl, 0);
            arcs[l] = a;
            arcs[nl + l] = b;
            if (theorems12_on(pattern_rule(spec, status, table.labels, arcs), table.labels[l], spec,
                              parts))
              per_label[l].emplace_back(a, b);
          }
      for (const auto& v : per_label)
        if (v.empty()) return;
      // Every combination over the labels, kept if connected.
      std::vector<size_t> choice(nl, 0);
      while (true) {
        std::vector<uint64_t> arcs(2 * nl, 0);
        for (size_t l = 0; l < nl; ++l) {
          arcs[l] = per_label[l][choice[l]].first;
          arcs[nl + l] = per_label[l][choice[l]].second;
        }
        const Rule r = pattern_rule(spec, status, table.labels, arcs);
        if (rule_components(r, table.labels).size() == 1)
          table.patterns.push_back(ComponentPattern{status, arcs, cycle_condition(r, reading)});
        size_t l = 0;
        while (l < nl && ++choice[l] == per_label[l].size()) choice[l++] = 0;
        if (l == nl) break;
      }
    };
    tuples(0, 0);
  }
  return table;
}

ComponentPattern component_pattern(const Rule& r, std::vector<std::string> nodes,
                                   const std::vector<int>& labels) {
  auto status = [&](const std::string& name) {
    if (!r.left().find(name)) return 2;
    return r.right().find(name) ? 0 : 1;
  };
  std::stable_sort(nodes.begin(), nodes.end(), [&](const std::string& x, const std::string& y) {
    return status(x) < status(y);
  });
  const size_t k = nodes.size(), nl = labels.size();
  ComponentPattern p;
  for (const auto& name : nodes) p.status.push_back(status(name));
  p.arcs.assign(2 * nl, 0);
  for (bool right : {false, true}) {
    const DGraph& g = right ? r.right() : r.left();
    for (graph::ArcId a : g.arc_slots()) {
      if (!g.arc_alive(a)) continue;
      const auto l = std::find(labels.begin(), labels.end(), g.arc(a).label);
      const auto x = std::find(nodes.begin(), nodes.end(), g.name(g.arc(a).src));
      const auto y = std::find(nodes.begin(), nodes.end(), g.name(g.arc(a).tgt));
      if (l == labels.end() || x == nodes.end() || y == nodes.end()) continue;
      p.arcs[(right ? nl : 0) + static_cast<size_t>(l - labels.begin())] |=
          uint64_t{1} << (static_cast<size_t>(x - nodes.begin()) * k +
                          static_cast<size_t>(y - nodes.begin()));
    }
  }
  return p;
}

size_t pattern_variables(size_t k, size_t labels) { return 2 * k + 2 * labels * k * k; }

PatternBits pattern_bits(const ComponentPattern& p, size_t labels) {
  const size_t k = p.nodes();
  PatternBits bits{};
  auto set = [&](size_t v) { bits[v / 64] |= uint64_t{1} << (v % 64); };
  for (size_t x = 0; x < k; ++x) {
    if (p.status[x] != 2) set(2 * x);
    if (p.status[x] != 1) set(2 * x + 1);
  }
  for (size_t side = 0; side < 2; ++side)
    for (size_t l = 0; l < labels; ++l)
      for (size_t x = 0; x < k; ++x)
        for (size_t y = 0; y < k; ++y)
          if (p.arc(side == 1, l, labels, x, y)) set(2 * k + ((side * labels + l) * k + x) * k + y);
  return bits;
}

std::vector<PatternCube> verdict_cubes(const CycleTable& table, bool verdict) {
  const size_t nl = table.labels.size();
  auto inside = [](const PatternBits& p, const PatternBits& care, const PatternBits& value) {
    return (p[0] & care[0]) == value[0] && (p[1] & care[1]) == value[1];
  };
  std::vector<PatternCube> out;
  for (size_t k = 1; k <= static_cast<size_t>(table.max_nodes); ++k) {
    const size_t vars = pattern_variables(k, nl);
    if (vars > 128) throw std::logic_error("verdict_cubes: more than 128 pattern variables");
    // `failing` are the patterns to cover (verdict `verdict`), `holding` those to keep out.
    std::vector<PatternBits> holding, failing;
    for (const ComponentPattern& p : table.patterns)
      if (p.nodes() == k) (p.holds == verdict ? failing : holding).push_back(pattern_bits(p, nl));
    PatternBits all{};
    for (size_t v = 0; v < vars; ++v) all[v / 64] |= uint64_t{1} << (v % 64);
    std::vector<bool> covered(failing.size(), false);
    for (size_t f = 0; f < failing.size(); ++f) {
      if (covered[f]) continue;
      PatternCube c{k, verdict, all, failing[f]};
      for (size_t v = vars; v-- > 0;) {
        PatternBits care = c.care;
        care[v / 64] &= ~(uint64_t{1} << (v % 64));
        const PatternBits value{c.value[0] & care[0], c.value[1] & care[1]};
        bool clean = true;
        for (const PatternBits& h : holding)
          if (inside(h, care, value)) {
            clean = false;
            break;
          }
        if (clean) {
          c.care = care;
          c.value = value;
        }
      }
      for (size_t g = f; g < failing.size(); ++g)
        if (!covered[g] && inside(failing[g], c.care, c.value)) covered[g] = true;
      out.push_back(c);
    }
  }
  return out;
}

}  // namespace gmr::smt
