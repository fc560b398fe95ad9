// A concrete rule's application on a symbolic map (map_encoding.hpp) as Z3 formulas (thesis
// Defs. 24-25, 32; docs/verify.md):
//   match       m: L -> G injective and label-preserving (Def. 24, Assumption 1): every L-arc
//               u -i-> w is sent to the G-arc m(u) -> alpha_i(m(u)), i.e. alpha_i(m(u)) = m(w).
//               Two parallel L-arcs (same ends and label) never match a map (one arc per label at
//               a dart). With `fixed_match` (symmetry breaking) the k-th node of L is sent to dart
//               k: every match is one of these up to a renaming of the darts.
//   dangling    the gluing condition on a mono: every G-arc incident to the image of a deleted node
//               (its outgoing i-arc and its incoming i-arc, from alpha_i^-1) is the image of an
//               L-arc.
//   H           the nodes of H are the live darts (active, not the image of a deleted node) and one
//               numeral k + a per added node a; for every H node x and label i, the candidate
//               outgoing i-arcs are G's arc x -> alpha_i(x) unless it is the image of a deleted
//               L-arc, and every added R-arc whose source is x (same for incoming arcs).
//   violation   "H violates X at x": I_H(i) at x — not exactly one outgoing and one incoming i-arc;
//               O_H(i) at x — h_i(h_i(x)) != x; C_H(i,j) at x — h_j h_i h_j h_i (x) != x, where h_i
//               is an uninterpreted function equal, on every live x, to the target of x's first
//               present outgoing i-arc. Where I_H holds everywhere, h_i is exactly H's i-arcs, so O
//               and C are exact; where it fails somewhere the violation is true anyway. Hence
//               `breaks_model()` holds iff H is not a map of the model (Def. 32).
#pragma once
#include <z3++.h>

#include <vector>

#include "checker/smt/map_encoding.hpp"
#include "model/graph/constraints.hpp"
#include "model/rewrite/rule.hpp"

namespace gmr::smt {
using rewrite::Rule;

class DerivationEncoding {
 public:
  DerivationEncoding(const MapEncoding& map, const Rule& rule, bool fixed_match = true);

  const MapEncoding& map() const { return map_; }
  // The image of L node v.
  const z3::expr& match(graph::Node v) const { return m_[v]; }
  // The H node of R node r: m(left_of(r)) when preserved, the numeral capacity + index when added.
  z3::expr h_node(graph::Node r) const;
  // Index of an added R node among the added nodes (the numeral capacity + index in H).
  unsigned num_h_nodes() const { return map_.capacity() + static_cast<unsigned>(added_.size()); }
  const std::vector<graph::Node>& added_nodes() const { return added_; }

  // m is an injective label-preserving morphism into the active darts.
  z3::expr_vector match_constraints() const;
  // The dangling (gluing) condition.
  z3::expr dangling_condition() const;
  // H node x exists (live dart or added node).
  z3::expr alive(unsigned x) const;
  // "H violates the constraint at node x" (j only for Cycle).
  z3::expr violates(Constraint kind, unsigned x, int i, int j = -1) const;
  // Definitions of the functions h_i (needed by violates(NonOrientation|Cycle)).
  z3::expr_vector h_definitions() const;
  // Some node of H violates some constraint of the model.
  z3::expr breaks_model() const;
  // The same, with the violations looked for only at the nodes the rewrite touches: the images of
  // the preserved nodes and the added nodes (docs/verify.md, "Local violations"): I_H can only
  // change there; if I_H holds everywhere, h_i is a permutation, an O_H violation at x shows at
  // h_i(x) too, and a C_H(i,j) violation shows on every node of its alternating path (as an ijij
  // or a jiji violation), one of which is touched, as an untouched path is a path of G.
  z3::expr breaks_model_local() const;

 private:
  struct Candidate {
    z3::expr present;
    z3::expr end;  // target of an outgoing, source of an incoming arc
  };
  std::vector<Candidate> out_arcs(unsigned x, int i) const;
  std::vector<Candidate> in_arcs(unsigned x, int i) const;
  std::vector<Candidate> out_arcs(const z3::expr& X, bool g_dart, int i) const;
  std::vector<Candidate> in_arcs(const z3::expr& X, bool g_dart, int i) const;
  z3::expr alive_term(const z3::expr& X) const;
  z3::expr exactly_one(const std::vector<Candidate>& cs) const;
  z3::expr h(int i, const z3::expr& x) const { return h_[i](x); }

  const MapEncoding& map_;
  const Rule& rule_;
  HandleVector<graph::Node, z3::expr> m_;       // L node -> its image
  std::vector<graph::Node> added_;              // the added R nodes
  HandleVector<graph::Node, int> added_index_;  // R node -> index among added (or -1)
  std::vector<z3::func_decl> h_;                // per label
};

}  // namespace gmr::smt
