// The condition plug-in interface of `gmr validate-condition` (docs/verify.md, "Condition
// plug-ins"). Header-only and self-contained (standard library only): a plug-in is a shared
// library compiled against this file alone,
//     c++ -std=c++20 -shared -fPIC -I<gmr source> my_condition.cpp -o libmycond.so
// that defines the entry symbol (C linkage)
//     extern "C" const gmr_condition* gmr_condition_v1();
// (the macro GMR_CONDITION_PLUGIN writes it), or, for a condition on rule schemes,
//     extern "C" const gmr_scheme_condition* gmr_scheme_condition_v1();
// (GMR_SCHEME_CONDITION_PLUGIN), or both. The returned description must stay valid while the
// library is loaded. A condition is a predicate on concrete rules (thesis §3.3: a syntactic
// condition on L and R): `holds(rule)` returns true when the rule satisfies it. It may throw; a
// plug-in must be built with the same C++ standard library as gmr (std::vector and std::string
// cross the boundary).
//
// The rule as the predicate sees it (RuleView): the model (G-map labels 0..n, O-map labels
// 1..n), the nodes of L and R with their names and status, and the arcs of each side, each an
// i-arc source -> target with its status (preserved arcs: same ends and label on both sides,
// thesis Assumption 4). A link between two distinct nodes is two opposite arcs; a loop is one arc.
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace gmr::condition {

// The model's enums (MapKind, ElemStatus, Side of model/graph/elem_status.hpp), repeated so that a
// plug-in compiles against this header alone.
enum class Model { GMap, OMap };
enum class Status { Preserved, Deleted, Added };
enum class Side { Left, Right };

struct Arc {
  unsigned source = 0, target = 0;  // node indices of the side
  int label = 0;
  Status status = Status::Preserved;
};

struct Node {
  std::string name;
  Status status = Status::Preserved;
  std::optional<unsigned> other;  // the same node on the other side (preserved nodes)
};

struct Graph {
  std::vector<Node> nodes;
  std::vector<Arc> arcs;
};

struct RuleView {
  std::string name;
  Model model = Model::GMap;
  int n = 0;
  Graph left, right;

  const Graph& side(Side s) const { return s == Side::Left ? left : right; }
  int lowest_label() const { return model == Model::OMap ? 1 : 0; }
  std::vector<int> labels() const {
    std::vector<int> out;
    for (int i = lowest_label(); i <= n; ++i) out.push_back(i);
    return out;
  }
  // Labels whose links are involutions (non-orientation applies): all but 1 for an O-map.
  bool involutive(int i) const { return !(model == Model::OMap && i == 1); }
  // Pairs (i, j), i + 2 <= j, of the cycle constraint.
  std::vector<std::pair<int, int>> cycle_pairs() const {
    std::vector<std::pair<int, int>> out;
    for (int i = lowest_label(); i <= n; ++i)
      for (int j = i + 2; j <= n; ++j) out.emplace_back(i, j);
    return out;
  }
  // Indices of the i-arcs leaving (resp. entering) node v of a side.
  std::vector<unsigned> out_arcs(Side s, unsigned v, int i) const {
    std::vector<unsigned> out;
    const auto& a = side(s).arcs;
    for (unsigned k = 0; k < a.size(); ++k)
      if (a[k].source == v && a[k].label == i) out.push_back(k);
    return out;
  }
  std::vector<unsigned> in_arcs(Side s, unsigned v, int i) const {
    std::vector<unsigned> out;
    const auto& a = side(s).arcs;
    for (unsigned k = 0; k < a.size(); ++k)
      if (a[k].target == v && a[k].label == i) out.push_back(k);
    return out;
  }
  // The index of an arc u -i-> v of a side, if any.
  std::optional<unsigned> find_arc(Side s, unsigned u, unsigned v, int i) const {
    const auto& a = side(s).arcs;
    for (unsigned k = 0; k < a.size(); ++k)
      if (a[k].source == u && a[k].target == v && a[k].label == i) return k;
    return std::nullopt;
  }
  // Follows the word (a sequence of labels) from v along the unique arc of each label; nullopt
  // when an arc is missing or not unique. Returns the end node.
  std::optional<unsigned> follow(Side s, unsigned v, const std::vector<int>& word) const {
    for (int i : word) {
      const auto out = out_arcs(s, v, i);
      if (out.size() != 1) return std::nullopt;
      v = side(s).arcs[out[0]].target;
    }
    return v;
  }
  // The word labels a cycle from v (e.g. {i, j, i, j}: an ijij-cycle, Def. 29).
  bool is_cycle(Side s, unsigned v, const std::vector<int>& word) const {
    auto e = follow(s, v, word);
    return e && *e == v;
  }
};

// A Jerboa rule scheme (thesis Defs. 86-87) as a scheme condition sees it (optional entry point
// gmr_scheme_condition_v1, below). Each node has a label: the generalised orbit type <o^v>, read
// positionally against the scheme's <o> (position p carries dimension orbit[p] to label[p], or
// deletes it when label[p] is -1, Jerboa's `_`): the node's implicit arcs. Explicit arcs are
// undirected a -dim- b (a == b: a loop). Statuses by name, as for rules.
struct SchemeNode {
  std::string name;
  std::vector<int> label;  // -1: `_`
  Status status = Status::Preserved;
};

struct SchemeArc {
  unsigned a = 0, b = 0;
  int dim = 0;
};

struct SchemeGraph {
  std::vector<SchemeNode> nodes;
  std::vector<SchemeArc> arcs;
};

struct SchemeView {
  std::string name;
  int n = 0;               // the scheme rewrites n-G-maps
  std::vector<int> orbit;  // <o>
  SchemeGraph left, right;
  std::vector<std::string> hooks;  // L node names; the first is the reference hook

  const SchemeGraph& side(Side s) const { return s == Side::Left ? left : right; }
  // Explicit d-arcs at node v (a loop counts once).
  unsigned explicit_arcs(Side s, unsigned v, int d) const {
    unsigned k = 0;
    for (const auto& a : side(s).arcs) k += a.dim == d && (a.a == v || a.b == v);
    return k;
  }
  // All d-arcs at v: the explicit ones and the label positions carrying d (thesis Alg. 1).
  unsigned arcs(Side s, unsigned v, int d) const {
    unsigned k = explicit_arcs(s, v, d);
    for (int x : side(s).nodes[v].label) k += x == d;
    return k;
  }
};

}  // namespace gmr::condition

// What a plug-in exports.
extern "C" {
struct gmr_condition {
  const char* name;         // short name, shown in reports
  const char* description;  // one line
  bool (*holds)(const gmr::condition::RuleView& rule);
};
}

// Optional: a condition on rule schemes (validated through instantiation on the schemes given with
// --schemes). A plug-in may export either entry point or both.
extern "C" {
struct gmr_scheme_condition {
  const char* name;
  const char* description;
  bool (*holds)(const gmr::condition::SchemeView& scheme);
};
}

#define GMR_SCHEME_CONDITION_PLUGIN(NAME, DESCRIPTION, FN)           \
  extern "C" const gmr_scheme_condition* gmr_scheme_condition_v1() { \
    static const gmr_scheme_condition c{NAME, DESCRIPTION, FN};      \
    return &c;                                                       \
  }

// Defines the entry symbol gmr_condition_v1 returning {name, description, fn}.
#define GMR_CONDITION_PLUGIN(NAME, DESCRIPTION, FN)      \
  extern "C" const gmr_condition* gmr_condition_v1() {   \
    static const gmr_condition c{NAME, DESCRIPTION, FN}; \
    return &c;                                           \
  }
