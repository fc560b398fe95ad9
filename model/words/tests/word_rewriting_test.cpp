// Words, conjugates and the conjugate rewriting system R_{N,E} (thesis Defs. 43, 52; Lemmas 9–11;
// Ex. 55/56/59).
#include "model/words/word_rewriting.hpp"

#include <gtest/gtest.h>

#include <ostream>
#include <random>
#include <set>

#include "checker/scheme_checker.hpp"
#include "model/core/error.hpp"

using namespace gmr;
using namespace gmr::words;
using namespace gmr::checker;

namespace gmr {
// Readable gtest messages for words.
inline void PrintTo(const Letter& l, std::ostream* os) { *os << to_string(PathWord{l}); }
}  // namespace gmr

namespace {

PathWord w(const char* s) { return parse_word(s); }

std::set<std::string> rule_strings(const RewritingSystem& R) {
  std::set<std::string> out;
  for (const auto& r : R.rules()) out.insert(to_string(r.lhs) + "->" + to_string(r.rhs));
  return out;
}

// F14 system: D = 0..3, N = {1,3}, O = {0,2}, E = {(0,1),(0,2),(1,2),(1,3)} (Ex. 55).
RewritingSystem f14() { return RewritingSystem({1, 3}, {0, 2}, {{0, 1}, {0, 2}, {1, 2}, {1, 3}}); }

}  // namespace

TEST(Words, ParsePrintConjugate) {
  const PathWord x = w("~2 3130201");
  ASSERT_EQ(x.size(), 8u);
  EXPECT_EQ(x[0], (Letter{2, true}));
  EXPECT_EQ(x[1], (Letter{3, false}));
  EXPECT_EQ(to_string(x), "~23130201");
  EXPECT_TRUE(w("").empty());
  EXPECT_TRUE(w("eps").empty());
  EXPECT_TRUE(w(" e p s ").empty());
  EXPECT_EQ(to_string(PathWord{}), "eps");
  EXPECT_THROW(w("2~"), Error);
  EXPECT_THROW(w("~~2"), Error);
  EXPECT_THROW(w("2a"), Error);
  // conj(w1..wn) = ~wn..~w1, ~~d = d (Def. 43).
  EXPECT_EQ(to_string(conj(w("21"))), "~1~2");
  EXPECT_EQ(conj(conj(x)), x);
  EXPECT_EQ(to_string(conj(w("1~20"))), "~02~1");
  EXPECT_TRUE(conj(PathWord{}).empty());
}

TEST(F14, Ex55RuleListExactly) {
  const RewritingSystem R = f14();
  const std::set<std::string> expected = {
      "11->eps", "33->eps", "0~0->eps", "~00->eps", "2~2->eps", "~22->eps",  // cancellations
      "10->~01", "1~0->01", "21->1~2",  "~21->12",  "31->13",   "20->~0~2", "~2~0->02"};
  EXPECT_EQ(rule_strings(R), expected);
  // Ex. 56: mixed-polarity swaps are not rules (Lemma 11: R' would be unsound).
  EXPECT_EQ(R.rule_for({2, false}, {0, true}), nullptr);  // 2~0 -> 0~2
  EXPECT_EQ(R.rule_for({2, true}, {0, false}), nullptr);  // ~20 -> ~02
  // N letters: ~1 is 1, ~3 is 3 inside the system.
  EXPECT_EQ(R.normalize(w("~1~3~0")), w("13~0"));
  EXPECT_NE(R.rule_for({1, true}, {1, false}), nullptr);  // ~11 = 11 -> eps
  EXPECT_THROW(R.normalize(Letter{4, false}), Error);
}

TEST(F14, Ex55ReductionChainStepByStep) {
  const RewritingSystem R = f14();
  // The printed chain; each step must be a one-step rewrite of the previous word.
  const std::vector<const char*> chain = {"~2 3130201", "~2 1330201", "~2 10201", "~2 10~0~21",
                                          "~21~21",     "12~21",      "11",       "eps"};
  for (size_t k = 0; k + 1 < chain.size(); ++k) {
    const auto next = R.one_step(w(chain[k]));
    EXPECT_NE(std::find(next.begin(), next.end(), w(chain[k + 1])), next.end())
        << chain[k] << " -/-> " << chain[k + 1];
  }
  EXPECT_TRUE(R.is_normal(w("eps")));
  // The printed chain is not leftmost (~2 1330201 has ~21 at position 0), but it still reaches ε,
  // and so does every other derivation of this word.
  const auto lm = R.leftmost_derivation(w("~2 3130201"));
  EXPECT_EQ(lm.front(), w("~23130201"));
  EXPECT_TRUE(lm.back().empty());
  EXPECT_EQ(R.normal_forms(w("~2 3130201")), std::vector<PathWord>{PathWord{}});
  for (size_t k = 0; k + 1 < lm.size(); ++k) {
    const auto next = R.one_step(lm[k]);
    EXPECT_EQ(next.front(), lm[k + 1]);  // one_step lists positions left to right
  }
}

TEST(F14, Ex56NonConfluenceOf210) {
  const RewritingSystem R = f14();
  const auto step = R.one_step(w("210"));
  ASSERT_EQ(step.size(), 2u);
  EXPECT_EQ(step[0], w("1~20"));        // 21 -> 1~2
  EXPECT_EQ(step[1], w("2~01"));        // 10 -> ~01
  EXPECT_TRUE(R.is_normal(w("1~20")));  // ~20 is not a rule
  EXPECT_TRUE(R.is_normal(w("2~01")));  // 2~0 is not a rule
  EXPECT_EQ(R.normal_forms(w("210")), (std::vector<PathWord>{w("1~20"), w("2~01")}));
  // The leftmost derivation picks one of them: congruent() is not a valid test for this system.
  EXPECT_EQ(R.normal_form(w("210")), w("1~20"));
  EXPECT_FALSE(R.congruent(w("1~20"), w("2~01")));
}

TEST(F14, Ex59InOrientedSystem) {
  // R_{∅,{(1,2)}}: N = ∅, so 1 and 2 are oriented.
  const RewritingSystem R({}, {1, 2}, {{1, 2}});
  EXPECT_EQ(R.normal_forms(w("1~11")), std::vector<PathWord>{w("1")});
  EXPECT_TRUE(R.congruent(w("1~11"), w("1")));
  EXPECT_FALSE(R.congruent(w("11"), w("1")));    // Fig. 4.24b: `1` vs `11` (E9)
  EXPECT_FALSE(R.congruent(w("11"), w("eps")));  // 1 is oriented: 11 does not cancel
  EXPECT_EQ(rule_strings(R), (std::set<std::string>{"1~1->eps", "~11->eps", "2~2->eps", "~22->eps",
                                                    "21->~1~2", "~2~1->12"}));
}

TEST(Systems, GmapRulesAndConfluence) {
  const RewritingSystem R = RewritingSystem::gmap(3);
  // §5.3: ii -> ε, ji -> ij for j >= i+2.
  EXPECT_EQ(rule_strings(R), (std::set<std::string>{"00->eps", "11->eps", "22->eps", "33->eps",
                                                    "20->02", "30->03", "31->13"}));
  EXPECT_TRUE(R.non_oriented() == (std::set<int>{0, 1, 2, 3}));
  EXPECT_TRUE(R.oriented().empty());
  // Confluence on every word of length <= 5 over 0..3 (Lemma: |O| <= 1 and E transitive).
  std::vector<PathWord> words{PathWord{}};
  size_t checked = 0;
  for (int len = 1; len <= 5; ++len) {
    std::vector<PathWord> next;
    for (const PathWord& x : words)
      if (static_cast<int>(x.size()) == len - 1)
        for (int d = 0; d <= 3; ++d) {
          PathWord y = x;
          y.push_back({d, false});
          next.push_back(y);
        }
    for (const PathWord& x : next) {
      const auto nfs = R.normal_forms(x);
      ASSERT_EQ(nfs.size(), 1u) << to_string(x);
      ASSERT_EQ(nfs[0], R.normal_form(x)) << to_string(x);
      ++checked;
    }
    words.insert(words.end(), next.begin(), next.end());
  }
  EXPECT_EQ(checked, 4u + 16 + 64 + 256 + 1024);
  EXPECT_EQ(R.normal_form(w("0202")), PathWord{});
  EXPECT_EQ(R.normal_form(w("02")),
            w("02"));  // a length-2 cycle word is not ε (no rule of Def. 52 applies)
  EXPECT_EQ(R.normal_form(w("31303")), w("103"));  // 31303 -> 13303 -> 103 (1,0 do not commute)
}

TEST(Systems, OmapRulesAndConfluence) {
  const RewritingSystem R = RewritingSystem::omap(4);
  // §5.3: 1~1, ~11, kk (k >= 2) -> ε; ji -> ij (i,j >= 2, j >= i+2); j1 -> ~1j, j~1 -> 1j (j >= 3).
  EXPECT_EQ(rule_strings(R),
            (std::set<std::string>{"1~1->eps", "~11->eps", "22->eps", "33->eps", "44->eps",
                                   "42->24", "31->~13", "3~1->13", "41->~14", "4~1->14"}));
  // 2-O-map: E = ∅, only the cancellations 1~1, ~11, 22.
  EXPECT_EQ(rule_strings(RewritingSystem::omap(2)),
            (std::set<std::string>{"1~1->eps", "~11->eps", "22->eps"}));
  // Confluence on all words of length <= 4 over {1,~1,2,3,4}.
  const std::vector<Letter> alphabet = {{1, false}, {1, true}, {2, false}, {3, false}, {4, false}};
  std::vector<PathWord> layer{PathWord{}};
  for (int len = 1; len <= 4; ++len) {
    std::vector<PathWord> next;
    for (const PathWord& x : layer)
      for (Letter l : alphabet) {
        PathWord y = x;
        y.push_back(l);
        next.push_back(y);
      }
    for (const PathWord& x : next) ASSERT_EQ(R.normal_forms(x).size(), 1u) << to_string(x);
    layer = next;
  }
  EXPECT_EQ(R.normal_form(w("31")), w("~13"));
  // C(1,3): a 1313-path is a cycle (1313 -> 1~133 -> 1~1 -> ε), while 313~1 -> ~1 3 3 ~1 -> ~1~1.
  EXPECT_TRUE(R.congruent(w("1313"), w("eps")));
  EXPECT_EQ(R.normal_form(w("313~1")), w("~1~1"));
}

TEST(Systems, RejectsBadParameters) {
  EXPECT_THROW(RewritingSystem({1}, {1}, {}), Error);
  EXPECT_THROW(RewritingSystem({0, 1}, {}, {{1, 0}}), Error);
  EXPECT_THROW(RewritingSystem({0, 1}, {}, {{0, 5}}), Error);
}

// A direct G-map normal form (ii -> ε, ji -> ij for j >= i+2, leftmost rewrite first), the
// reference R_{0..n, (0..n)_{+2}} and the scheme checker's gmap_word_normal_form must agree with.
static std::vector<int> reference_gmap_normal_form(std::vector<int> w) {
  bool changed = true;
  while (changed) {
    changed = false;
    for (size_t k = 0; k + 1 < w.size(); ++k) {
      if (w[k] == w[k + 1]) {
        w.erase(w.begin() + static_cast<long>(k), w.begin() + static_cast<long>(k) + 2);
        changed = true;
        break;
      }
      if (w[k] >= w[k + 1] + 2) {
        std::swap(w[k], w[k + 1]);
        changed = true;
        break;
      }
    }
  }
  return w;
}

TEST(Systems, AgreesWithSchemeCheckerGmapNormalForm) {
  // R_{0..n, (0..n)_{+2}} (Def. 52), the direct G-map normal form above and the scheme checker's
  // gmap_word_normal_form must agree on random G-map words.
  std::mt19937 rng(12345);
  for (int n = 1; n <= 4; ++n) {
    const RewritingSystem R = RewritingSystem::gmap(n);
    std::uniform_int_distribution<int> dim(0, n), len(0, 12);
    for (int t = 0; t < 400; ++t) {
      std::vector<int> dims(static_cast<size_t>(len(rng)));
      for (int& d : dims) d = dim(rng);
      std::vector<int> nf_checker = reference_gmap_normal_form(dims);
      ASSERT_EQ(gmap_word_normal_form(n, dims), nf_checker);
      ASSERT_EQ(word_of_dims(nf_checker), R.normal_form(word_of_dims(dims)))
          << "n=" << n << " " << to_string(word_of_dims(dims));
    }
  }
}
