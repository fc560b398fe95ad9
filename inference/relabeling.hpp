// The choice of a node's relabeling in topological folding (thesis Alg. 6 step 2.2, §7.2.3 and
// §7.2.5; docs/inference.md).
//
// For a new node v and each position p of the orbit type <o>, the candidates are the dimensions j
// such that (a,v) –j– (c,v), where c is the o_p-neighbour of the start dart a in the hook orbit.
// The thesis requires the relabeling to be injective and leaves the choice among several candidates
// to "a heuristic … to construct a plausible relabeling function". The deterministic rule used here
// (documented choice):
//  1. candidates of a position are ordered: the identity j = o_p first, then increasing j;
//  2. a *loop* position (c = a: a has an o_p-loop) may also be read as no implicit arc (`_`), the
//     j-loop then becoming an explicit loop of step 2.1. Implicit is tried first ("aggressive", the
//     thesis' default); for the dimensions of LoopPolicy::explicit_loops (Jerboa's "excluded
//     loops") the implicit reading is not offered at all ("conservative");
//  3. `_` (deletion, no check needed, thesis §7.2.3) is the last option of every position, but at
//     a non-loop position it is admissible only when each of the position's candidates is taken by
//     another position (the thesis removes the dimensions used by earlier positions from C and
//     deletes the position when none is left). A non-loop position deleted while one of its
//     candidates j stays unused would meet an arc failure on j in step 2.1 ((a,v) –j– (c,v) with
//     c != a), so such assignments are never useful: the node is then a relabeling failure, as in
//     the thesis;
//  4. the first assignment, in the lexicographic order of positions and candidates, that is
//     injective and passes the full relabeling check of every position is taken (backtracking over
//     positions; |o| <= n+1 is tiny).
// Found by the exhaustive completeness test (inference/tests/completeness_test.cpp): offering `_`
// only to positions without candidates missed schemes on maps where a@o_p = a@o_q.
// When no assignment exists the node is a relabeling failure. `enumerate` lists every consistent
// assignment in the same order (the plurality of answers, thesis §7.6).
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "model/core/orbit_type.hpp"

namespace gmr::inference {

struct LoopPolicy {
  DimMask explicit_loops = 0;  // dimensions whose loops are always explicit
  bool implicit(int j) const { return !((explicit_loops >> j) & 1u); }
};

struct RelabelingCandidates {
  // candidates[p]: ordered dimensions (OrbitType::kHole = `_`), already following rules 1–2.
  std::vector<std::vector<int>> candidates;
  std::vector<uint8_t> loop;  // loop[p]: c == a (the start dart has an o_p-loop)
};

// Orders the raw candidate set of a position (rule 1 and 2). `dims` are the j with (a,v)–j–(c,v);
// o_p the position's dimension; loop: c == a.
std::vector<int> order_candidates(std::vector<int> dims, int o_p, bool loop,
                                  const LoopPolicy& policy);

struct RelabelingChoice {
  std::optional<std::vector<int>> label;  // the chosen relabeling, or none
  // On failure: the first position none of whose candidates passes the check (or, when every
  // position has one, the first position where injectivity blocks), and its last candidate tried.
  int failed_position = -1;
  int failed_dim = OrbitType::kHole;
};

// `passes(p, j)` is the full relabeling check of position p read as j (never called for `_`).
RelabelingChoice choose_relabeling(const RelabelingCandidates& c,
                                   const std::function<bool(size_t, int)>& passes);
std::vector<std::vector<int>> enumerate_relabelings(const RelabelingCandidates& c,
                                                    const std::function<bool(size_t, int)>& passes);

}  // namespace gmr::inference
