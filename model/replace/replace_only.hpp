// Replace only (Damiand & Nivoliers 2022 §7.1, Table 1: the hexahedral subdivision timed with "only
// the replace part", every cell being known to match its one pattern): the cells are replaced by a
// given pattern without a query, no word and no lookup. The cell's boundary still has to be mapped
// onto the pattern's: it is traversed breadth-first from a dart d given as matched with the
// pattern's start dart (StoreEntry::start), which numbers its darts in label order from d
// (cell_sweep.hpp), and the k-th labelled darts of the two boundaries correspond (Theorem 1).
// The traversal is checked against the pattern's boundary word (flags and neighbour labels in
// label order, ReplacementTemplate::word; linear, no hashing): a cell that does not match from d
// is left untouched and reported unmatched, never replaced wrongly. The isomorphism given by d is
// used in either mode (orientation is not checked). The replacement is query-replace's
// (cell_replacement.hpp).
#pragma once
#include <functional>
#include <vector>

#include "model/replace/query_replace.hpp"

namespace gmr::replace {

// Replaces every cell_dim-cell of the target (cell_dim: the pattern's) by store.patterns()[pattern],
// or only the cells of `starts`, each dart being the one matched with the pattern's start dart.
// Without a list, every cell is traversed from its smallest dart. Checks of the target and
// precondition as query_replace (Error(InvalidMap), Error(Usage)); a pattern index out of range,
// a dart that is not alive or a cell listed twice is Error(Usage) before anything is replaced.
// after_each (optional) runs after every replacement. The report counts the cells examined, the
// replacements (matched[pattern]), the cells left (unmatched, the dart each was traversed from)
// and the darts added.
QueryReplaceReport replace_only(FlaggedMap& target, const PatternStore& store, size_t pattern,
                                const std::vector<Dart>* starts = nullptr,
                                Precondition precondition = Precondition::CheckValidity,
                                const std::function<void()>& after_each = {});

}  // namespace gmr::replace
