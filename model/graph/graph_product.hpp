// Products of labelled graphs and the arc operations built from them (thesis §4.2.1–4.2.2,
// Def. 41, Ex. 42).
//
// Σ-graphs are gmr::DGraph with int labels (Σ is a list of ints).
//  * Product P ×_Σ Π (the pullback over the terminal 1_Σ): nodes V_P × V_Π — all pairs, isolated
//    ones included — and one arc (e,f): (s e, s f) -> (t e, t f) for every pair of arcs with
//    l(e) = l(f), with that label. Node (p,q) has id p·|V_Π| + q and name "p,q" (node_str of each).
//  * Arc deletion: P × Δ_i, Δ_i = one node with a loop per letter of Σ \ {i}.
//  * Arc relabeling by ℜ ⊆ Σ² (at most one j per i; (i,i) keeps i, (i,j) renames i into j, an i
//    without pair is deleted), Def. 41: π_Σ(E_Σ(P) ×_{Σ²} Π_ℜ), with E_Σ the embedding that
//    replaces each i-arc by |Σ| parallel (i,j)-arcs, Π_ℜ one node with an (i,j)-loop per pair of ℜ
//    and π_Σ keeping the second component. `relabel_literal` builds exactly this (pairs (i,j) are
//    encoded as ints by `pair_label`); `relabel` does it directly on P.
#pragma once
#include <utility>
#include <vector>

#include "model/graph/dgraph.hpp"

namespace gmr::graph {

using Alphabet = std::vector<int>;                    // Σ, distinct labels
using Relabeling = std::vector<std::pair<int, int>>;  // ℜ ⊆ Σ²

// P ×_Σ Π. Throws Error(Schema) when an arc label of P or Π is not in Σ (an empty Σ accepts every
// label: the product over all labels).
DGraph product(const DGraph& P, const DGraph& Pi, const Alphabet& sigma = {});
inline Node product_node(const DGraph& Pi, Node p, Node q) {
  return Node(static_cast<uint32_t>(p.index() * Pi.num_nodes() + q.index()));
}

// The terminal graph 1_Σ: one node, one loop per letter.
DGraph terminal(const Alphabet& sigma);
// Δ_i = 1_{Σ \ {i}} seen as a Σ-graph.
DGraph delta(const Alphabet& sigma, int i);
// P × Δ_i: P without its i-arcs (node p of P is node p of the result).
DGraph delete_arcs(const DGraph& P, const Alphabet& sigma, int i);

// The int label of the pair (i,j) of Σ² (index(i)·|Σ| + index(j)) and back.
int pair_label(const Alphabet& sigma, int i, int j);
std::pair<int, int> label_pair(const Alphabet& sigma, int code);
// E_Σ(P): every i-arc becomes |Σ| parallel arcs labelled pair_label(i, j), j ∈ Σ.
DGraph embed_pairs(const DGraph& P, const Alphabet& sigma);
// Π_ℜ: one node with a pair_label(i,j)-loop per pair of ℜ. Throws Error(Schema) when ℜ gives two
// images to one letter or uses a letter outside Σ.
DGraph relabeling_graph(const Alphabet& sigma, const Relabeling& rel);
// π_Σ: keeps the second component of every pair label.
DGraph project_second(const DGraph& G, const Alphabet& sigma);

// Def. 41 literally: π_Σ(E_Σ(P) ×_{Σ²} Π_ℜ). Node p of P is node p of the result.
DGraph relabel_literal(const DGraph& P, const Alphabet& sigma, const Relabeling& rel);
// The same directly: same nodes and names as P, arc i kept as ℜ(i) or dropped.
DGraph relabel(const DGraph& P, const Alphabet& sigma, const Relabeling& rel);

}  // namespace gmr::graph
