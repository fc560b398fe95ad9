// The query-replace driver (Damiand & Nivoliers 2022 §4, §6.3): every i-cell of the target
// (faces for i = 2, volumes for i = 3) is looked up in the store by the word from its first start
// dart (pattern_store.hpp); a cell whose word is stored has its interior replaced
// (cell_replacement.hpp) through the isomorphism f read off the cell's word and the equal word of
// the pattern (the k-th labelled darts correspond); other cells are left untouched and reported.
// The cells are those of the input map (the darts a replacement adds are not swept), so each is
// replaced at most once. A face of a 3-G-map is looked up on the half-face of its smallest dart.
// Boundary automorphisms: the cell's first start dart (in its traversal order) is sent to the
// pattern's first start dart (in its local order) with the same word, so the result is
// deterministic; a key holding several patterns uses the first one, or the selector's choice.
// A cell is first compared with the word the previous cell was looked up by, numbered along it
// from its dart (word_traversal.hpp): when every letter agrees, its word from that dart is that
// stored word, so the dart is its first start dart and the lookup would give the same match (a
// sequence of cells of one pattern is looked up without a traversal of its own or a hash).
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "model/replace/flagged_map.hpp"
#include "model/replace/pattern_store.hpp"

namespace gmr::replace {

struct QueryReplaceReport {
  Mode mode = Mode::Unoriented;
  int cell_dim = 2;
  size_t cells = 0;             // cells examined
  std::vector<size_t> matched;  // per pattern of the store
  std::vector<Dart> unmatched;  // one dart of each cell left untouched
  size_t ambiguous_keys = 0;    // matches whose key held several patterns
  size_t darts_added = 0;
  size_t replaced() const;
};

// Throws Error(InvalidMap) when the target is not a valid G-map of dimension cell_dim or
// cell_dim + 1 (or, in oriented mode, not orientable).
// The cells are met by one sweep (cell_sweep.hpp) and each is replaced when it is looked up (a
// replacement touches no other cell's boundary; docs/query-replace.md). With a list of cells or a
// selector, every cell is looked up first and the matches are then replaced in the order of the
// cells (the same result, dart for dart), so that an error leaves the map unchanged.
// after_each (optional) runs after every replacement (tests assert validity there; with a list or
// a selector, the copies of all matches are added before the first replacement, so the darts of
// the replacements still to come are then isolated free darts); progress
// (optional) receives (cells done, cells) every 4096 cells and at the end.
// select (optional) chooses among the patterns of a key holding several (§6.4: deliberate
// duplicates need outside information, e.g. geometry or vertex values): it receives the candidates
// (in insertion order), the target and a dart of the cell, and returns an index into the
// candidates; without it, the first candidate is used. An index out of range is Error(Usage).
// only (optional): the cells to examine, one dart each (default: every cell of the map); a cell
// named twice is Error(Usage), before anything is replaced.
// precondition: CheckValidity (default) validates the target first; AssumeValid skips it, for a
// caller that has validated the map itself (the map is then read as a valid G-map; an invalid one
// gives undefined results).
enum class Precondition { CheckValidity, AssumeValid };
using DuplicateSelector =
    std::function<size_t(const std::vector<StoreEntry>&, const FlaggedMap&, Dart)>;
// The start shared by query_replace and replace_only (replace_only.hpp): checks the target (a
// G-map of dimension cell_dim or cell_dim + 1, cell_dim 2 or 3: Error(Usage) otherwise; valid
// unless AssumeValid: Error(InvalidMap)), sizes its flags and returns an empty report.
QueryReplaceReport begin_replacement(FlaggedMap& target, const PatternStore& store, int cell_dim,
                                     Precondition precondition);
QueryReplaceReport query_replace(FlaggedMap& target, const PatternStore& store, int cell_dim,
                                 const std::function<void()>& after_each = {},
                                 const std::function<void(size_t, size_t)>& progress = {},
                                 const DuplicateSelector& select = {},
                                 const std::vector<Dart>* only = nullptr,
                                 Precondition precondition = Precondition::CheckValidity);

// An upper bound of the darts query_replace(target, store, cell_dim) adds: per cell, the largest
// interior of the store's patterns of that dimension, twice for a face of a 3-G-map with two
// half-faces. Splitting edges changes no cell, so the bound computed before an e-pattern holds
// after it: a sequence (edges, faces, volumes) can reserve its final size once
// (FlaggedMap::reserve).
size_t replacement_room(const Map& g, const PatternStore& store, int cell_dim);
// The bound of a sequence replacing the cells of each dimension of cell_dims in turn: the sum of
// replacement_room over them, with the half-faces and half-volumes of a 3-G-map counted in one
// sweep (count_half_faces_and_volumes, half_cells.hpp).
size_t replacement_room(const Map& g, const PatternStore& store, const std::vector<int>& cell_dims);
// The same bound from the number of darts alone, without a sweep: a cell a pattern replaces has
// as many darts as that pattern's boundary (a half-face each side of a face of a 3-G-map), and
// half-cells of one dimension share no dart, so a map of `darts` darts has at most darts / b
// replaced half-cells of a dimension whose patterns' smallest boundary has b darts, each given at
// most the largest interior i; the dimensions of cell_dims are replaced in turn, each on the darts
// the previous ones left. `darts` counts the map when the first of them runs (after any edge
// split). Exact when every cell matches a pattern with both the smallest boundary and the largest
// interior (a uniform subdivision: one pattern per dimension); with patterns of very different
// sizes it reserves more than replacement_room, which counts the cells.
size_t replacement_room_bound(size_t darts, const PatternStore& store,
                              const std::vector<int>& cell_dims);

}  // namespace gmr::replace
