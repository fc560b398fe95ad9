// The pattern store (Damiand & Nivoliers 2022 §6.3): a hash table from boundary signature to
// patterns, built for one mode. A key may hold several patterns (§6.4 allows deliberate
// duplicates; query-replace then takes the first one, in insertion order, and counts the case).
// Keys are the minimal flagged word preceded by the cell dimension, so f- and v-patterns never
// share a key.
#pragma once
#include <string>
#include <unordered_map>
#include <vector>

#include "model/replace/flagged_word.hpp"
#include "model/replace/pattern.hpp"
#include "model/replace/replacement_template.hpp"

namespace gmr::replace {

struct StoreEntry {
  size_t pattern = 0;          // index in patterns()
  uint32_t start = 0;          // local boundary index of the minimal word's start dart
  uint32_t automorphisms = 0;  // boundary automorphisms (preserving flags, and D+ if oriented)
  // Some boundary automorphism does not extend to the whole pattern: the result of a replacement
  // depends on the minimal start dart chosen (the paper's Fig. 4; ties are broken deterministically).
  bool ambiguous = false;
};

// Whether every automorphism of the pattern's boundary in `mode` (start dart e.start mapped to
// another minimal start) extends to an automorphism of the pattern preserving flags.
bool boundary_automorphisms_extend(const Pattern& p, Mode mode, const StoreEntry& e);

// A cell looked up in the store: the patterns of its key (nullptr: none) and the cell's start dart
// (local index) whose word is the key, the first in local order.
struct StoreMatch {
  const std::vector<StoreEntry>* hits = nullptr;
  uint32_t start = 0;
};

class PatternStore {
 public:
  explicit PatternStore(Mode mode) : mode_(mode) {}
  Mode mode() const { return mode_; }

  // Adds a pattern; in oriented mode an unorientable pattern is refused (Error(Schema)).
  void add(Pattern p);
  const std::vector<Pattern>& patterns() const { return patterns_; }
  const StoreEntry& entry(size_t pattern) const { return entries_[pattern]; }
  // The pattern's interior compiled against its boundary in the label order of entry().start.
  const ReplacementTemplate& replacement(size_t pattern) const { return templates_[pattern]; }

  // The patterns whose boundary has this key (nullptr if none).
  const std::vector<StoreEntry>* find(const Word& key) const;
  // Looks a cell's boundary up (§6.3). Keys are grouped by a profile of cheap isomorphism
  // invariants (cell dimension, number of darts, number and invariant of the start darts): no key
  // with the cell's profile is a miss without any word; a single one is compared with the cell's
  // words start by start, stopping at the first equal word (equal words: equal signatures,
  // Theorem 1), without computing the cell's minimum; otherwise the signature is computed and
  // hashed. The three give the same answer and the same start dart.
  StoreMatch match(const BoundaryGraph& cell, int cell_dim) const;
  // Groups of patterns (indices) sharing a key: the duplicates of §6.4.
  std::vector<std::vector<size_t>> duplicates() const;
  size_t keys() const { return table_.size(); }

 private:
  Mode mode_;
  std::vector<Pattern> patterns_;
  std::vector<StoreEntry> entries_;
  std::vector<ReplacementTemplate> templates_;
  std::vector<Word> key_of_;
  std::unordered_map<Word, std::vector<StoreEntry>, WordHash> table_;
  // Profile -> the distinct keys with that profile: each key's word (without its dimension
  // prefix) and its patterns in table_ (nodes of an unordered_map do not move).
  struct Keyed {
    Word word;
    const std::vector<StoreEntry>* entries;
  };
  std::unordered_map<Word, std::vector<Keyed>, WordHash> profiles_;
};

// The store key of a boundary graph signed in `mode`, with the entry's start and automorphisms.
Word store_key(const BoundaryGraph& b, int cell_dim, Mode mode, StoreEntry* entry = nullptr);

}  // namespace gmr::replace
