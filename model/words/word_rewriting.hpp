// Words over conjugated dimensions and the conjugate rewriting system R_{N,E} (thesis §4.2,
// Def. 43; §4.6, Def. 52, Lemmas 9–11).
//
//  * A letter of D̄ = D ∪ {~d | d ∈ D} is a dimension with a conjugated flag; a word is a sequence
//    of letters, conj(w_1..w_k) = ~w_k .. ~w_1 and ~~d = d (Def. 43).
//  * R_{N,E} (Def. 52), for non-oriented dimensions N, oriented dimensions O and exchangeable pairs
//    E ⊆ {(i,j) | i < j}: inside the system ~d := d for d ∈ N (so D̄ = N ⊔ O ⊔ ~O), and the rules
//    are
//      (i ~i, ε)            for every letter i of D̄;
//      (j i, ~i ~j)          for (i,j) ∈ (N∪O)² ∪ (N∪~O)² with (||i||,||j||) ∈ E,
//    i.e. swap an adjacent pair whose higher dimension comes first and conjugate both letters; both
//    letters must be non-conjugated or both conjugated (N letters count as both).
//  * Noetherian always (Lemma 10); confluent for G-maps (N = 0..n, O = ∅, E = (0..n)_{+2}) and
//  O-maps
//    (N = 2..n, O = {1}, E = (1..n)_{+2}), where the normal form is unique and found by the
//    leftmost derivation; not confluent in general (Lemma 11; Ex. 56: `210`).
//
// Text form: letters are digits, "~" conjugates the next digit, spaces are ignored, "" or "eps"
// is the empty word: "~2 3130201". Dimensions are single digits (0..9), as in the thesis.
#pragma once
#include <compare>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "model/core/map_spec.hpp"

namespace gmr::words {

struct Letter {
  int dim = 0;
  bool conj = false;  // ~dim
  friend bool operator==(const Letter&, const Letter&) = default;
  friend auto operator<=>(const Letter&, const Letter&) = default;
};
// A word of D̄* (the thesis' "word"; named PathWord because gmr::Word is the signature's word,
// model/signature.hpp). It labels w-paths.
using PathWord = std::vector<Letter>;

inline Letter conj(Letter l) { return {l.dim, !l.conj}; }
// conj(w_1..w_k) = ~w_k .. ~w_1 (Def. 43).
PathWord conj(const PathWord& w);
PathWord concat(const PathWord& a, const PathWord& b);
// A word of non-conjugated letters (e.g. the labels along a path).
PathWord word_of_dims(const std::vector<int>& dims);

// "~2 3130201" -> letters; "" and "eps" -> ε. Throws Error(Parse) on anything else (a "~" not
// followed by a digit, another character).
PathWord parse_word(std::string_view text);
// The inverse of parse_word without spaces; ε prints as "eps".
std::string to_string(const PathWord& w);

class RewritingSystem {
 public:
  struct RewriteRule {
    PathWord lhs, rhs;
    friend bool operator==(const RewriteRule&, const RewriteRule&) = default;
    friend auto operator<=>(const RewriteRule&, const RewriteRule&) = default;
  };

  // Throws Error(Schema) when N and O intersect or a pair of E is not (i < j) over N ∪ O.
  RewritingSystem(std::set<int> N, std::set<int> O, std::vector<std::pair<int, int>> E);
  // The system of a map kind: N its involutive labels, O its oriented ones, E its cycle pairs.
  static RewritingSystem of(const MapSpec& spec);
  // n-G-maps: N = 0..n, O = ∅, E = (0..n)_{+2}.
  static RewritingSystem gmap(int n);
  // n-O-maps: N = 2..n, O = {1}, E = (1..n)_{+2}.
  static RewritingSystem omap(int n);

  const std::set<int>& non_oriented() const { return N_; }
  const std::set<int>& oriented() const { return O_; }
  const std::vector<std::pair<int, int>>& exchangeable() const { return E_; }

  // ~d -> d for d ∈ N (the convention of §4.6). Throws Error(Range) for a dimension outside N ∪ O.
  Letter normalize(Letter l) const;
  PathWord normalize(const PathWord& w) const;

  // The rules of Def. 52, sorted; lhs and rhs are normalized.
  const std::vector<RewriteRule>& rules() const { return rules_; }
  // The rule whose left-hand side is the (normalized) pair (a,b), or nullptr. Left-hand sides are
  // pairwise distinct.
  const RewriteRule* rule_for(Letter a, Letter b) const;

  // All words reachable in exactly one step (one per position where a rule applies).
  std::vector<PathWord> one_step(const PathWord& w) const;
  bool is_normal(const PathWord& w) const;
  // Every normal form reachable from w (exhaustive search; the system is noetherian, and words
  // never grow, so the search is finite). Sorted, without duplicates.
  std::vector<PathWord> normal_forms(const PathWord& w) const;
  // The leftmost derivation w = w_0 -> w_1 -> ... -> w_k (w_k normal): at each step the rule is
  // applied at the first position where one applies.
  std::vector<PathWord> leftmost_derivation(const PathWord& w) const;
  PathWord normal_form(const PathWord& w) const { return leftmost_derivation(w).back(); }
  // Congruence test w <->* w' by equal (leftmost) normal forms: valid only when the system is
  // confluent (G-maps, O-maps); see normal_forms for the general search.
  bool congruent(const PathWord& a, const PathWord& b) const {
    return normal_form(a) == normal_form(b);
  }

 private:
  std::set<int> N_, O_;
  std::vector<std::pair<int, int>> E_;
  std::vector<RewriteRule> rules_;
};

}  // namespace gmr::words
