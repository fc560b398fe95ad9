// Bounded proofs of Theorems 1 and 2 (incident arcs with the dangling part, non-orientation) in
// their model-level form on models without cycle pairs, for EVERY rule of the family at once: the
// rule is symbolic too (checker/smt/symbolic_validation.hpp; proofs/README.md). Each test states
// its bounds: rules over at most `nodes` nodes with arcs on the labels listed, maps of at most
// `darts` darts.
#include "proofs/bounded.hpp"

using namespace gmr;
using namespace gmr::proofs;

// 1-G-maps, labels 0 and 1, 3 nodes (1466908 rules), 8 darts.
TEST(Proof, Thm1And2_Symbolic_1GMaps_Labels01_Nodes3_Darts8) {
  prove_conditions_symbolic(1, MapKind::GMap, {0, 1}, 3, 8);
}

// 2-O-maps, labels 1 and 2, 3 nodes, 8 darts.
TEST(Proof, Thm1And2_Symbolic_2OMaps_Labels12_Nodes3_Darts8) {
  prove_conditions_symbolic(2, MapKind::OMap, {1, 2}, 3, 8);
}

// 1-G-maps, labels 0 and 1, 4 nodes (2016665962 rules), 8 darts.
TEST(Proof, Thm1And2_Symbolic_1GMaps_Labels01_Nodes4_Darts8) {
  prove_conditions_symbolic(1, MapKind::GMap, {0, 1}, 4, 8);
}

// 2-O-maps, labels 1 and 2, 4 nodes, 8 darts.
TEST(Proof, Thm1And2_Symbolic_2OMaps_Labels12_Nodes4_Darts8) {
  prove_conditions_symbolic(2, MapKind::OMap, {1, 2}, 4, 8);
}
