// Bounded proofs of Theorems 1 and 2 for every rule of at most 4 nodes at once (about 2.0e9 rules
// on two labels), rule symbolic (checker/smt/symbolic_validation.hpp; proofs/README.md).
#include "proofs/bounded.hpp"

using namespace gmr;
using namespace gmr::proofs;

// 1-G-maps, labels 0 and 1, 4 nodes (2016665962 rules), 8 darts.
TEST(ProofSlow, Thm1And2_Symbolic_1GMaps_Labels01_Nodes4_Darts8) {
  prove_conditions_symbolic(1, MapKind::GMap, {0, 1}, 4, 8);
}

// 2-O-maps, labels 1 and 2, 4 nodes, 8 darts.
TEST(ProofSlow, Thm1And2_Symbolic_2OMaps_Labels12_Nodes4_Darts8) {
  prove_conditions_symbolic(2, MapKind::OMap, {1, 2}, 4, 8);
}
