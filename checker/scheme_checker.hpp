// Static checker for Jerboa rule schemes (thesis §4.4–4.7 and Ch. 6).
//
// Diagnostics are the checker's one Diagnostic/Severity (diagnostic.hpp); JSON in
// docs/check-format.md.
//
// A scheme is read as a (W×D)-rule scheme (thesis Fig. 6.15 translation): an explicit arc a –d– b
// is an (ε,d)-arc in both directions (one loop arc when a == b), and label position p with o^v[p] =
// d is an (o[p], d)-loop on v. Arcs are preserved iff they have the same ends and the same full
// (w,d) label on both sides (Def. 46). The conditions checked, all local and syntactic:
//
// Jerboa's practical checks (code, severity):
//   S-orbit           error   <o> has `_`, repeats a dimension or uses one outside 0..n (or cannot
//                             be determined: no hook and no hole-free label)
//   S-label-arity     error   a node label does not have the arity of <o>
//   S-dim-range       error   a label entry or an arc dimension outside 0..n
//   S-duplicate-name  error   two nodes of one side share a name
//   S-dim-twice       error   a dimension used twice at a node (two label positions, a position and
//                             an explicit arc, or two explicit arcs). In L this is thesis E1 (no
//                             match into a G-map exists); in R it breaks incident arcs.
//   S-hook-hole       error   a hook whose label contains `_`
//   S-hook-orbit      error   the reference hook's label differs from <o>
//   S-no-hook         error   a connected component of L without hook
//   S-several-hooks   error   a connected component of L with two or more hooks
//   S-precondition    warning a Jerboa precondition (code) is present: it is not evaluated, the
//                             verdict is about the topology only
//   S-left-expression warning an embedding expression on an L-only node (ignored)
// Embeddings (condition "embeddings", when the scheme declares embeddings or has expressions):
//   E-*               the static embedding checks of embedding_check.hpp
// Incident arcs I_S(d), d in 0..n (Def. 49, Alg. 1):
//   I-preserved-node  error   E2: a preserved node has a d-arc in L but not in R, or conversely
//   I-deleted-node    error   E3: a deleted node without a d-arc in L (gluing/dangling condition)
//   I-added-node      error   E4: an added node without exactly one d-arc in R
// Non-orientation O_S(d): holds by construction for G-map schemes (explicit arcs are undirected,
// implicit loops carry self-conjugate letters, conj(i) = i); recorded as a satisfied condition.
// Cycle C_S(i,j), i+2 <= j (Def. 40 + Def. 55, Alg. 3, rewriting system R_{N,E} of Def. 52 for
// G-maps: ii -> ε, ji -> ij for j >= i+2, confluent; congruence = equal normal forms):
//   C-incoherent      error   E8: an (i,j)-optimal path has no coherent optimal path on the other
//                             side (same ends and core label word)
//   C-ambiguous       error   E8: it has two or more
//   C-word            error   E9: the coherent partner's W-word is not congruent
//   C-cycle-length    error   E10: an alternating (i,j)-cycle of length not in {2,4}
//   C-cycle-word      error   E11: the W-word of an ijij traversal does not reduce to ε (its
//                             instances do not close). Length-2 cycles are traversed twice and
//                             every rotation is read.
//   C-preserved-node  error   E12 (Def. 40.2): a preserved node with a DELETED i-arc (resp. j-arc)
//                             whose i-arc (j-arc) in R is neither on an alternating cycle nor on an
//                             optimal path of R
//   C-added-node      error   E13 (Def. 40.3): the same for an added node
//   C-skipped         note    C_S(i,j) not evaluated because a node has two i- or j-arcs
//
// Algorithm 3 versus Def. 40: the thesis' Algorithm 3 (lines 24–27) tests every preserved node
// having ANY i-arc in L, while Def. 40.2 concerns deleted arcs only. The default follows Def. 40;
// `algorithm3_strict` reproduces Algorithm 3 (tests show a scheme on which they disagree).
// ij-completion of L (Assumption 5) is not performed on schemes: Jerboa schemes match orbits whose
// implicit arcs are already complete; an L-side iji-path that is not closed in L is judged as is.
// Theorem 6 (cycle) is sufficient only: an accepted scheme preserves G-maps; a rejected one may
// still do so on all G-maps (tested by the property test, which looks for a witness).
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "checker/diagnostic.hpp"
#include "model/scheme/rule_scheme.hpp"

namespace gmr::checker {
using scheme::RuleScheme;

struct SchemeCheckOptions {
  bool algorithm3_strict = false;  // Algorithm 3 literally (see above)
  bool embeddings = true;  // the embedding checks (embedding_check.hpp); false: topology only
};

// The report of a scheme (subject Scheme; its text and gmr.check JSON: diagnostic.hpp).
CheckReport check_scheme(const RuleScheme& s, const SchemeCheckOptions& opt = {});

// Normal form of a G-map word of dimension n (letters = dimensions) under R_{N,E} for G-maps
// (Def. 52: ii -> ε, ji -> ij for j >= i+2): RewritingSystem::gmap(n).normal_form.
std::vector<int> gmap_word_normal_form(int n, const std::vector<int>& w);

}  // namespace gmr::checker
