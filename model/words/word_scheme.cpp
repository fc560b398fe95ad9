#include "model/words/word_scheme.hpp"

#include <algorithm>
#include <deque>

#include "model/core/error.hpp"

namespace gmr::words {
using namespace gmr::graph;
using namespace gmr::rewrite;

uint32_t WordGraphScheme::add_node(std::string name) {
  if (name.empty()) throw Error(ErrorCode::Schema, "empty node name", "scheme node");
  if (find(name))
    throw Error(ErrorCode::Schema, "duplicate node name \"" + name + "\"", "scheme node");
  nodes.push_back(std::move(name));
  return static_cast<uint32_t>(nodes.size() - 1);
}

std::optional<uint32_t> WordGraphScheme::find(const std::string& name) const {
  for (size_t k = 0; k < nodes.size(); ++k)
    if (nodes[k] == name) return static_cast<uint32_t>(k);
  return std::nullopt;
}

void WordGraphScheme::add_arc(const std::string& src, const std::string& tgt,
                              const std::string& word, int dim) {
  const auto s = find(src), t = find(tgt);
  if (!s) throw Error(ErrorCode::Schema, "unknown node \"" + src + "\"", "scheme arc");
  if (!t) throw Error(ErrorCode::Schema, "unknown node \"" + tgt + "\"", "scheme arc");
  arcs.push_back({*s, *t, parse_word(word), dim});
}

void WordGraphScheme::add_link(const std::string& a, const std::string& b, const std::string& word,
                               int dim) {
  add_arc(a, b, word, dim);
  const PathWord w = parse_word(word);
  if (a == b && conj(w) == w) return;
  add_arc(b, a, to_string(conj(w)), dim);
}

DGraph WordGraphScheme::core() const {
  DGraph g;
  for (const auto& n : nodes) g.add_node(n);
  for (const auto& a : arcs) g.add_arc(Node(a.src), Node(a.tgt), a.dim);  // node k is scheme node k
  return g;
}

DGraph instantiate_word_graph(const WordGraphScheme& S, const PatternGraph& P) {
  DGraph out;
  for (uint32_t n = 0; n < S.size(); ++n)
    for (Node u : P.graph.nodes()) out.add_node(P.graph.name(u) + ":" + S.nodes[n]);
  for (const WordArc& a : S.arcs) {
    const int l = P.label_of(a.word);
    if (l < 0)
      throw Error(ErrorCode::Schema,
                  "the word " + to_string(a.word) + " of a scheme arc is not in W",
                  "arc " + S.nodes[a.src] + " -> " + S.nodes[a.tgt]);
    // Every w-arc u -> u' of P gives the d-arc (u,src) -> (u',tgt).
    for (ArcId e : P.graph.arc_slots()) {
      if (!P.graph.arc_alive(e) || P.graph.arc(e).label != l) continue;
      out.add_arc(instance_node(P, a.src, P.graph.arc(e).src),
                  instance_node(P, a.tgt, P.graph.arc(e).tgt), a.dim);
    }
  }
  return out;
}

std::vector<std::optional<uint32_t>> WordRuleScheme::preserved_arcs() const {
  std::vector<std::optional<uint32_t>> out(left.arcs.size());
  std::vector<bool> used(right.arcs.size(), false);
  for (size_t k = 0; k < left.arcs.size(); ++k) {
    const WordArc& a = left.arcs[k];
    for (size_t m = 0; m < right.arcs.size(); ++m) {
      const WordArc& b = right.arcs[m];
      if (used[m] || b.dim != a.dim || b.word != a.word) continue;
      if (right.nodes[b.src] != left.nodes[a.src] || right.nodes[b.tgt] != left.nodes[a.tgt])
        continue;
      used[m] = true;
      out[k] = static_cast<uint32_t>(m);
      break;
    }
  }
  return out;
}

Rule WordRuleScheme::core() const { return Rule(left.core(), right.core(), n, kind, name); }

Rule instantiate_word_rule(const WordRuleScheme& S, const PatternGraph& P) {
  return Rule(instantiate_word_graph(S.left, P), instantiate_word_graph(S.right, P), S.n, S.kind,
              S.name);
}

std::optional<rewrite::NodeMap> propagate_match(const WordRuleScheme& S, const PatternGraph& P,
                                                const Rule& inst, const DGraph& G) {
  const auto hook = S.left.find(S.hook);
  if (!hook)
    throw Error(ErrorCode::Schema, "the hook \"" + S.hook + "\" is not a node of L", "hook");
  const DGraph& L = inst.left();
  HandleVector<Node, Node> m(L.num_nodes(), kNoNode);
  std::deque<Node> todo;
  for (Node u : P.graph.nodes()) {
    m[instance_node(P, *hook, u)] = P.origin[u];
    todo.push_back(instance_node(P, *hook, u));
  }
  auto assign = [&](Node x, Node img) {
    if (m[x] == kNoNode) {
      m[x] = img;
      todo.push_back(x);
      return true;
    }
    return m[x] == img;
  };
  while (!todo.empty()) {
    const Node x = todo.front();
    todo.pop_front();
    for (ArcId a : L.out_arcs(x)) {
      if (!L.arc_alive(a)) continue;
      const auto next = G.successors(m[x], L.arc(a).label);  // unique under I_G
      if (next.size() != 1 || !assign(L.arc(a).tgt, next[0])) return std::nullopt;
    }
    for (ArcId a : L.in_arcs(x)) {
      if (!L.arc_alive(a)) continue;
      const auto prev = G.predecessors(m[x], L.arc(a).label);
      if (prev.size() != 1 || !assign(L.arc(a).src, prev[0])) return std::nullopt;
    }
  }
  std::vector<Node> sorted = m;
  std::sort(sorted.begin(), sorted.end());
  if (!sorted.empty() && sorted.back() == kNoNode)
    return std::nullopt;  // unreachable from the hook
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
    return std::nullopt;  // not injective
  return m;
}

WordSchemeInstance instantiate_at(const Map& g, const WordRuleScheme& S,
                                  const std::vector<PathWord>& W, Dart d) {
  if (!g.alive(d)) throw Error(ErrorCode::Usage, "no dart " + std::to_string(d), "hook dart");
  const DGraph G = to_dgraph(g);
  const std::vector<Dart> darts = g.darts();  // node k of G is darts[k]
  const Node v(
      static_cast<uint32_t>(std::lower_bound(darts.begin(), darts.end(), d) - darts.begin()));
  PatternGraph Pv = component(pattern_graph(G, W), v);
  Rule rule = instantiate_word_rule(S, Pv);
  const auto m = propagate_match(S, Pv, rule, G);
  if (!m)
    throw Error(ErrorCode::Usage, "the instantiated left-hand side does not match at the hook",
                "dart " + std::to_string(d));
  std::vector<Dart> match;
  for (Node x : *m) match.push_back(darts[x.index()]);
  return WordSchemeInstance{std::move(Pv), std::move(rule), std::move(match)};
}

}  // namespace gmr::words
