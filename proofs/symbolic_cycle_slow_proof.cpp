// Theorems 1-3 for every 2-G-map rule of at most 4 nodes at once (labels 0, 1, 2;
// 84,071,858,566,898 rules), maps of at most 8 darts, C_r from the checker's table of component
// patterns (checker/smt/cycle_table.hpp, symbolic_cycle.hpp); and
// the symbolic engine on 2-G-maps (labels 0, 1, 2; checker/smt/symbolic_validation.hpp) against
// the enumerator rule by rule (checker/smt/condition_validation.hpp, Engine::Enum), on every
// built-in condition, rules of at most 2 nodes, maps of 4 to 6 darts: the same verdicts, and the
// symbolic witnesses confirmed by the enumerator (proofs/README.md).
#include <cstdio>
#include <string>

#include "checker/smt/rule_verifier.hpp"
#include "proofs/bounded.hpp"

using namespace gmr;
using namespace gmr::proofs;

// Theorems 1-3 for every 2-G-map rule of at most 4 nodes at once (labels 0, 1, 2;
// 84,071,858,566,898 rules), maps of at most 8 darts, C_r from the table of every component
// pattern of at most 4 nodes (no lazy lemma needed).
TEST(ProofSlow, Thm1To3_Symbolic_2GMaps_Labels012_Nodes4_Darts8) {
  const smt::SymbolicReport r = prove_conditions_symbolic(2, MapKind::GMap, {0, 1, 2}, 4, 8);
  EXPECT_EQ(r.cycle_patterns, 109678u);  // 6 + 81 + 2,111 + 107,480 connected patterns
  EXPECT_EQ(r.cycle_lemmas, 0u);
}

TEST(ProofSlow, Thm1To3_Symbolic_2GMaps_Nodes2_Darts4To6_AgreesWithEnumerator) {
  for (unsigned bound = 4; bound <= 6; ++bound)
    for (const auto& c : smt::builtin_conditions()) {
      const smt::ValidationOptions o{.n = 2,
                                     .kind = MapKind::GMap,
                                     .labels = {0, 1, 2},
                                     .max_nodes = 2,
                                     .bound = bound,
                                     .engine = smt::Engine::Enum};
      const smt::SymbolicReport s = smt::validate_symbolic(c.name, o);
      const smt::ValidationReport e = smt::validate_condition(
          c.name,
          [&](const std::vector<rewrite::Rule>& rules) {
            std::vector<bool> out;
            for (const auto& x : rules) out.push_back(c.holds(x));
            return out;
          },
          o);
      std::printf("%s%s", smt::to_text(s).c_str(), smt::to_text(e).c_str());
      ASSERT_TRUE(s.sound_decided && s.complete_decided);
      EXPECT_EQ(s.sound(), e.sound()) << c.name << ", " << bound << " darts";
      EXPECT_EQ(s.complete(), e.complete()) << c.name << ", " << bound << " darts";
      if (s.smallest_unsound) {
        const smt::VerifyResult v =
            smt::verify_enum(s.smallest_unsound->rule, bound, smt::Semantics::Consistency);
        EXPECT_FALSE(v.preserves) << c.name;
      }
      if (s.smallest_incomplete) {
        EXPECT_FALSE(c.holds(s.smallest_incomplete->rule));
        const smt::VerifyResult v =
            smt::verify_enum(s.smallest_incomplete->rule, bound, smt::Semantics::Consistency);
        EXPECT_TRUE(v.applicable && v.preserves) << c.name;
      }
    }
}
