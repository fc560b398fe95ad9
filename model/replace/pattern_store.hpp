// The pattern store (Damiand & Nivoliers 2022 §6.3): a hash table from boundary signature to
// patterns, built for one mode. A key may hold several patterns (§6.4 allows deliberate
// duplicates; query-replace then takes the first one, in insertion order, and counts the case).
// Keys are the minimal flagged word preceded by the cell dimension, so f- and v-patterns never
// share a key. Cells are looked up by one word: the store also keeps the word of every start dart
// of each pattern's start set (start_darts), so a cell needs the word from any one of its own start
// darts and a hash lookup (a word from s determines the boundary up to an isomorphism sending s to
// the start, Theorem 1; the start sets are mapped onto each other by isomorphisms).
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
  // depends on the minimal start dart chosen (the paper's Fig. 4; ties are broken
  // deterministically).
  bool ambiguous = false;
};

// Whether every automorphism of the pattern's boundary in `mode` (start dart e.start mapped to
// another minimal start) extends to an automorphism of the pattern preserving flags.
bool boundary_automorphisms_extend(const Pattern& p, Mode mode, const StoreEntry& e);

// A cell looked up in the store: the patterns of its key (nullptr: none), the cell's start dart
// (local index) whose word was looked up, and per hit the isomorphism onto the pattern's boundary:
// ranks[h][k] is the position, in the cell's label order from `start`, of the dart matched with the
// k-th dart of hit h's boundary in its label order from StoreEntry::start (the order of its
// replacement template).
struct StoreMatch {
  const std::vector<StoreEntry>* hits = nullptr;
  uint32_t start = 0;
  const std::vector<std::vector<uint32_t>>* ranks = nullptr;
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
  // Looks a cell's boundary up (§6.3) by the word from its first start dart (in local order) and
  // one hash lookup: the same patterns as find(store_key(cell)) (a word from a start dart equals a
  // stored word iff the minimal signatures are equal, Theorem 1).
  StoreMatch match(const BoundaryGraph& cell, int cell_dim) const;
  // The same for a cell whose word from its start dart `start` (a dart of its start set) is
  // `key`, preceded by the cell dimension.
  StoreMatch match_word(const Word& key, uint32_t start) const;
  // Number of stored lookup words (one per pattern start dart, automorphic starts counted once)
  // and their letters.
  size_t lookup_words() const { return lookup_.size(); }
  size_t lookup_letters() const { return lookup_letters_; }
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
  // Word from a start dart (with the dimension prefix) -> the patterns of its key in table_ (nodes
  // of an unordered_map do not move) and, per pattern, the ranks of StoreMatch.
  struct Lookup {
    const std::vector<StoreEntry>* entries = nullptr;
    std::vector<std::vector<uint32_t>> ranks;
  };
  std::unordered_map<Word, Lookup, WordHash> lookup_;
  void index_start_words(const Pattern& p, const std::vector<StoreEntry>& list,
                         const std::vector<uint32_t>& ref);
  size_t lookup_letters_ = 0;
};

// The store key of a boundary graph signed in `mode`, with the entry's start and automorphisms.
Word store_key(const BoundaryGraph& b, int cell_dim, Mode mode, StoreEntry* entry = nullptr);

}  // namespace gmr::replace
