// Rule-scheme isomorphism (thesis Def. 90, Algorithm 7).
//
// Two Jerboa rule schemes are compared on their joint representations κ(L,R): nodes of L and R
// (each flagged L or R), explicit arcs labelled 0..n, and one κ-arc between the two copies of every
// preserved node. Every node has at most one neighbour per label in 0..n ∪ {κ}.
// Node signature = (side, decoration, δ_0 … δ_n, δ_κ), δ_i = 0 without i-neighbour, 1 for an
// i-neighbour other than itself, 2 for an i-loop. The side flag is added here
// (otherwise an L and an R node could be swapped).
// Algorithm 7: compare the signature histograms, then root a joint BFS at a node of the rarest
// signature and try every candidate image; the BFS follows the non-loop arcs and requires equal
// signatures at both ends (with the [D] guard against re-enqueueing, and a full-cover check).
// Disconnected joint representations: components are matched one by one with backtracking
// (exponential in the number of components, as the thesis notes; folding never produces one).
//
// Decisions where the text is silent (docs/inference.md):
//  * hooks are not compared ("all rules on <> are isomorphic up to hook choice"), nor names,
//    embedding expressions or preconditions: this is the topology of the rule;
//  * by default decorations are compared up to ONE global permutation of positions, applied to
//    every node of the first scheme: the same rule folded from another full-decoration hook has its
//    positions permuted (its hook orbit is the relabeled copy of O). `exact_positions` compares
//    decorations position by position, as Alg. 7 is printed.
#pragma once
#include <optional>
#include <vector>

#include "model/scheme/rule_scheme.hpp"

namespace gmr::inference {
using scheme::RuleScheme;

struct SchemeIsomorphismOptions {
  bool exact_positions = false;
};

struct SchemeIsomorphism {
  std::vector<uint32_t> left, right;  // node of the first scheme -> node of the second, per side
  std::vector<size_t> positions;      // positions[q] = position of the first scheme read at q
};

// Both schemes must have at most one explicit arc per dimension at each node (otherwise
// Error(Usage): such a scheme is not combinatorial and has no joint representation as required).
std::optional<SchemeIsomorphism> scheme_isomorphism(const RuleScheme& a, const RuleScheme& b,
                                                    const SchemeIsomorphismOptions& opt = {});
inline bool schemes_isomorphic(const RuleScheme& a, const RuleScheme& b,
                               const SchemeIsomorphismOptions& opt = {}) {
  return scheme_isomorphism(a, b, opt).has_value();
}

}  // namespace gmr::inference
