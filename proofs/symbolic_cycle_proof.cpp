// Bounded proof of Theorems 1-3 (incident arcs, non-orientation, the cycle condition on the model
// completion) on 2-G-maps for EVERY rule of the family at once: the rule is symbolic, C_r decided
// through the concrete cycle checker's lemmas (checker/smt/symbolic_validation.hpp;
// proofs/README.md). The test states its bounds: rules over at most `nodes` nodes with arcs on
// labels 0, 1, 2, maps of at most `darts` darts.
#include "proofs/bounded.hpp"

using namespace gmr;
using namespace gmr::proofs;

// 2-G-maps, labels 0, 1, 2, 2 nodes (123967 rules), 8 darts.
TEST(Proof, Thm1To3_Symbolic_2GMaps_Labels012_Nodes2_Darts8) {
  const smt::SymbolicReport r = prove_conditions_symbolic(2, MapKind::GMap, {0, 1, 2}, 2, 8);
  EXPECT_GT(r.cycle_patterns, 0u);  // the cycle condition was decided, not skipped
  EXPECT_EQ(r.cycle_lemmas, 0u);    // every component is tabulated
}

// 2-G-maps, labels 0, 1, 2, 3 nodes (1,572,721,536 rules), 8 darts: every component pattern of at
// most 3 nodes tabulated (2,198), no lazy lemma.
TEST(Proof, Thm1To3_Symbolic_2GMaps_Labels012_Nodes3_Darts8) {
  const smt::SymbolicReport r = prove_conditions_symbolic(2, MapKind::GMap, {0, 1, 2}, 3, 8);
  EXPECT_EQ(r.cycle_patterns, 2198u);
  EXPECT_EQ(r.cycle_lemmas, 0u);
}
