#include "model/graph/graph_product.hpp"

#include <algorithm>
#include <string>

#include "model/core/error.hpp"

namespace gmr::graph {

namespace {

size_t index_of(const Alphabet& sigma, int i, const char* where) {
  const auto it = std::find(sigma.begin(), sigma.end(), i);
  if (it == sigma.end())
    throw Error(ErrorCode::Schema, "label " + std::to_string(i) + " is not in the alphabet Σ",
                where);
  return static_cast<size_t>(it - sigma.begin());
}

void check_labels(const DGraph& g, const Alphabet& sigma, const char* where) {
  if (sigma.empty()) return;
  for (ArcId a : g.arc_slots())
    if (g.arc_alive(a)) index_of(sigma, g.arc(a).label, where);
}

}  // namespace

DGraph product(const DGraph& P, const DGraph& Pi, const Alphabet& sigma) {
  check_labels(P, sigma, "product: left factor");
  check_labels(Pi, sigma, "product: right factor");
  DGraph out;
  for (Node p : P.nodes())
    for (Node q : Pi.nodes()) out.add_node(P.node_str(p) + "," + Pi.node_str(q));
  for (ArcId e : P.arc_slots()) {
    if (!P.arc_alive(e)) continue;
    const Arc& ae = P.arc(e);
    for (ArcId f : Pi.arc_slots()) {
      if (!Pi.arc_alive(f)) continue;
      const Arc& af = Pi.arc(f);
      if (ae.label != af.label) continue;
      out.add_arc(product_node(Pi, ae.src, af.src), product_node(Pi, ae.tgt, af.tgt), ae.label);
    }
  }
  return out;
}

DGraph terminal(const Alphabet& sigma) {
  DGraph g;
  const Node v = g.add_node("*");
  for (int i : sigma) g.add_arc(v, v, i);
  return g;
}

DGraph delta(const Alphabet& sigma, int i) {
  index_of(sigma, i, "delta");
  Alphabet rest;
  for (int j : sigma)
    if (j != i) rest.push_back(j);
  return terminal(rest);
}

DGraph delete_arcs(const DGraph& P, const Alphabet& sigma, int i) {
  return product(P, delta(sigma, i), sigma);
}

int pair_label(const Alphabet& sigma, int i, int j) {
  return static_cast<int>(index_of(sigma, i, "pair") * sigma.size() + index_of(sigma, j, "pair"));
}

std::pair<int, int> label_pair(const Alphabet& sigma, int code) {
  const size_t k = sigma.size();
  if (code < 0 || static_cast<size_t>(code) >= k * k)
    throw Error(ErrorCode::Range, "not a pair label: " + std::to_string(code), "pair");
  return {sigma[static_cast<size_t>(code) / k], sigma[static_cast<size_t>(code) % k]};
}

// A graph with the nodes of G (same ids and names) and, for every live arc a of G, the arcs that
// emit(out, a) adds: the common shape of E_Σ, π_Σ and the direct relabeling.
template <class Emit>
DGraph map_arcs(const DGraph& G, Emit emit) {
  DGraph out;
  for (Node p : G.nodes()) out.add_node(G.name(p));
  for (ArcId e : G.arc_slots())
    if (G.arc_alive(e)) emit(out, G.arc(e));
  return out;
}

DGraph embed_pairs(const DGraph& P, const Alphabet& sigma) {
  check_labels(P, sigma, "embed_pairs");
  return map_arcs(P, [&](DGraph& out, const Arc& a) {
    for (int j : sigma) out.add_arc(a.src, a.tgt, pair_label(sigma, a.label, j));
  });
}

DGraph relabeling_graph(const Alphabet& sigma, const Relabeling& rel) {
  for (size_t k = 0; k < rel.size(); ++k)
    for (size_t l = k + 1; l < rel.size(); ++l)
      if (rel[k].first == rel[l].first)
        throw Error(ErrorCode::Schema,
                    "relabeling gives two images to " + std::to_string(rel[k].first), "ℜ");
  DGraph g;
  const Node v = g.add_node("*");
  for (auto [i, j] : rel) g.add_arc(v, v, pair_label(sigma, i, j));
  return g;
}

DGraph project_second(const DGraph& G, const Alphabet& sigma) {
  return map_arcs(G, [&](DGraph& out, const Arc& a) {
    out.add_arc(a.src, a.tgt, label_pair(sigma, a.label).second);
  });
}

DGraph relabel_literal(const DGraph& P, const Alphabet& sigma, const Relabeling& rel) {
  // Π_ℜ has one node, so node p of E_Σ(P) × Π_ℜ is p·1 + 0 = p.
  return project_second(product(embed_pairs(P, sigma), relabeling_graph(sigma, rel)), sigma);
}

DGraph relabel(const DGraph& P, const Alphabet& sigma, const Relabeling& rel) {
  relabeling_graph(sigma, rel);  // validates ℜ
  check_labels(P, sigma, "relabel");
  return map_arcs(P, [&](DGraph& out, const Arc& a) {
    for (auto [i, j] : rel)
      if (i == a.label) out.add_arc(a.src, a.tgt, j);
  });
}

}  // namespace gmr::graph
