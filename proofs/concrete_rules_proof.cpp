// Bounded proofs of Theorems 1-3 (incident arcs, non-orientation, cycle) for concrete rules, in
// their model-level form (thesis §3.4): on G-maps and O-maps, a rule satisfies the model's
// conditions iff every match on every map glues and yields a map of the model. Each test states its
// bounds: rules over at most `nodes` nodes with arcs on the labels listed, maps of at most `darts`
// darts (proofs/README.md: what "bounded" covers).
#include "proofs/bounded.hpp"

using namespace gmr;
using namespace gmr::proofs;

// Theorems 1 and 2 on 1-G-maps (no cycle pair): 2 nodes, labels 0 and 1, 4 darts.
TEST(Proof, Thm1And2_1GMaps_Labels01_Nodes2_Darts4) {
  prove_conditions(1, MapKind::GMap, {0, 1}, 2, 4);
}

// Theorem 2 needs three nodes (a permutation of two darts is an involution): label 0, 3 nodes, 5
// darts.
TEST(Proof, Thm2_1GMaps_Label0_Nodes3_Darts5) { prove_conditions(1, MapKind::GMap, {0}, 3, 5); }

// Theorem 3 on the cycle pair (0,2) of 2-G-maps: 2 nodes, labels 0 and 2, 4 darts.
TEST(Proof, Thm3_2GMaps_Labels02_Nodes2_Darts4) {
  prove_conditions(2, MapKind::GMap, {0, 2}, 2, 4);
}

// Theorems 1 and 2 on 1-G-maps with 6 darts.
TEST(Proof, Thm1And2_1GMaps_Labels01_Nodes2_Darts6) {
  prove_conditions(1, MapKind::GMap, {0, 1}, 2, 6);
}

// Theorem 3 on the cycle pair (0,2) with 6 darts.
TEST(Proof, Thm3_2GMaps_Labels02_Nodes2_Darts6) {
  prove_conditions(2, MapKind::GMap, {0, 2}, 2, 6);
}

// 8 darts: Theorem 2 with three nodes, Theorem 3 on (0,2), O-maps.
TEST(Proof, Thm2_1GMaps_Label0_Nodes3_Darts8) { prove_conditions(1, MapKind::GMap, {0}, 3, 8); }
TEST(Proof, Thm3_2GMaps_Labels02_Nodes2_Darts8) {
  prove_conditions(2, MapKind::GMap, {0, 2}, 2, 8);
}
TEST(Proof, Thm1And2_2OMaps_Labels12_Nodes2_Darts8) {
  prove_conditions(2, MapKind::OMap, {1, 2}, 2, 8);
}

// O-maps (beta_1 a permutation, no non-orientation on 1): 2 nodes, labels 1 and 2, 4 darts.
TEST(Proof, Thm1And2_2OMaps_Labels12_Nodes2_Darts4) {
  prove_conditions(2, MapKind::OMap, {1, 2}, 2, 4);
}

// Theorem 2 on O-maps' involutive label 2, three nodes, 4 darts.
TEST(Proof, Thm2_2OMaps_Label2_Nodes3_Darts4) { prove_conditions(2, MapKind::OMap, {2}, 3, 4); }

// The same statement through the enumerator (the second engine), 1-G-maps, 2 nodes, 4 darts.
TEST(Proof, Thm1And2_1GMaps_Labels01_Nodes2_Darts4_Enumerator) {
  prove_conditions(1, MapKind::GMap, {0, 1}, 2, 4, smt::Engine::Enum);
}
