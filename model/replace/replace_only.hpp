// Replace only (Damiand & Nivoliers 2022 §7.1, Table 1: the hexahedral subdivision timed with "only
// the replace part", every cell being known to match its one pattern): the cells are replaced by a
// given pattern without a query, no word computed and no lookup. The cell's boundary still has to
// be mapped onto the pattern's: from a dart d given as matched with the pattern's start dart
// (StoreEntry::start), the cell is numbered along the pattern's boundary word
// (ReplacementTemplate::word, flags and neighbour labels in label order) and checked against it in
// the same pass (word_traversal.hpp): when every letter agrees, the k-th numbered dart is the
// image of the pattern's k-th labelled boundary dart (Theorem 1); a cell that does not match
// from d is left untouched and reported unmatched, never replaced wrongly. The isomorphism given
// by d is used in either mode (orientation is not checked). The replacement is query-replace's
// (cell_replacement.hpp).
#pragma once
#include <functional>
#include <vector>

#include "model/replace/query_replace.hpp"

namespace gmr::replace {

// Replaces every cell_dim-cell of the target (cell_dim: the pattern's) by
// store.patterns()[pattern], or only the cells of `starts`, each dart being the one matched with
// the pattern's start dart. Without a list, every cell is traversed from its smallest dart. Checks
// of the target and precondition as query_replace (Error(InvalidMap), Error(Usage)); a pattern
// index out of range, a dart that is not alive or a cell listed twice is Error(Usage) before
// anything is replaced. after_each (optional) runs after every replacement. The report counts the
// cells examined, the replacements (matched[pattern]), the cells left (unmatched, the dart each was
// traversed from) and the darts added.
QueryReplaceReport replace_only(FlaggedMap& target, const PatternStore& store, size_t pattern,
                                const std::vector<Dart>* starts = nullptr,
                                Precondition precondition = Precondition::CheckValidity,
                                const std::function<void()>& after_each = {});

}  // namespace gmr::replace
