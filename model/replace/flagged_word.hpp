// Flagged BFS words and signatures of boundary graphs (Damiand & Nivoliers 2022, Alg. 1 and
// Defs. 3–5, lifted to G-maps; flags §4.3.2):
//  * labels: the start dart gets 1; darts are taken in label order and, for j = 0..m, the
//    neighbour y = nbr_j(x) is labelled when new (a free dart's loop emits its own label);
//  * the word lists, per dart in label order, its flag and then the labels of its m+1 neighbours
//    (length (m+2)|B|). The whole sequence, flags included, is minimised: minimising the unflagged
//    word first and appending the flags of an arbitrary tied start would not be canonical;
//  * start darts (start_darts below): the flagged darts if any dart is flagged (the set is
//    invariant under isomorphisms, so the minimum stays canonical), else all darts; in oriented
//    mode, only those in D+ (the paper's orientation-preserving isomorphisms of 3-maps).
//    Unoriented mode compares G-maps up to any isomorphism, reflections included;
//  * the number of start darts reaching the minimum is the number of automorphisms (preserving
//    flags, and orientation in oriented mode); ties are broken by the first start in local order.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "model/core/signature.hpp"
#include "model/replace/boundary_graph.hpp"

namespace gmr::replace {

enum class Mode { Unoriented, Oriented };
const char* to_string(Mode m);

// W(B, s) with flags (with_flags) or without them (the unflagged words of Alg. 1).
Word boundary_word(const BoundaryGraph& b, uint32_t start, bool with_flags = true);
// W(B, s) with flags, appended to `out` (no allocation once `out` is large enough).
void boundary_word(const BoundaryGraph& b, uint32_t start, Word& out);
// The same, and the local darts in label order from `start` into `order` (boundary_labeling) in
// the same traversal.
void boundary_word(const BoundaryGraph& b, uint32_t start, Word& out, std::vector<uint32_t>& order);
// W(B, 0) appended to `out` for a graph numbered breadth-first from its local dart 0, neighbours
// in order (cell_boundary): local index k is label k + 1, so the letters are the flags and the
// neighbours + 1, read off in local order (no traversal; boundary_word(b, 0, out) otherwise).
void numbered_boundary_word(const BoundaryGraph& b, Word& out);
// The local darts in label order from `start` (order[k] has label k+1).
std::vector<uint32_t> boundary_labeling(const BoundaryGraph& b, uint32_t start);
// The same into `order` (reused; no allocation once it is large enough).
void boundary_labeling(const BoundaryGraph& b, uint32_t start, std::vector<uint32_t>& order);

// The start darts of Def. 5 with flags: the flagged darts if any dart is flagged, else all darts
// (only those of D+ in oriented mode); for volume boundaries (arity 3), only those whose pair
// (size of their face, size of the face across their edge) is the smallest, `invariant` being that
// pair (0 for other arities). The pair is an isomorphism invariant, so the set is mapped onto
// itself by every isomorphism: the minimum over it is a canonical form and every start reaching
// it is kept (the automorphism count is unchanged). In local order.
struct StartSet {
  std::vector<uint32_t> darts;
  uint64_t invariant = 0;
};
StartSet start_darts(const BoundaryGraph& b, Mode mode, bool with_flags = true);

// The first dart of start_darts(b, mode).darts (UINT32_MAX when the set is empty), without
// building the set.
uint32_t first_start_dart(const BoundaryGraph& b, Mode mode);

struct CellSignature {
  Word word;                   // the minimal word (empty for an empty graph)
  uint32_t start = 0;          // local index of the first start dart reaching it
  uint32_t automorphisms = 0;  // number of start darts reaching it
};
// Words longer than 2^32-1 labels cannot occur: labels are uint32 (Error(Range) beyond).
// All starts are streamed in lockstep, dropping a start as soon as its word exceeds the smallest.
CellSignature minimal_signature(const BoundaryGraph& b, Mode mode, bool with_flags = true);
CellSignature minimal_signature(const BoundaryGraph& b, const StartSet& starts,
                                bool with_flags = true);
struct WordHash {
  size_t operator()(const Word& w) const noexcept;
};

}  // namespace gmr::replace
