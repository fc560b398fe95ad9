// Larger bounds of the concrete-rule proofs (label slow; proofs/README.md for times).
#include "proofs/bounded.hpp"

using namespace gmr;
using namespace gmr::proofs;

// All three labels of 2-G-maps: 2 nodes, labels 0, 1, 2 (123967 rules), 4 darts.
TEST(ProofSlow, Thm1To3_2GMaps_Labels012_Nodes2_Darts4) {
  prove_conditions(2, MapKind::GMap, {0, 1, 2}, 2, 4);
}

// 10 darts: Theorem 2 with three nodes on 1-G-maps, Theorem 3 on (0,2), O-maps.
TEST(ProofSlow, Thm2_1GMaps_Label0_Nodes3_Darts10) {
  prove_conditions(1, MapKind::GMap, {0}, 3, 10);
}
TEST(ProofSlow, Thm3_2GMaps_Labels02_Nodes2_Darts10) {
  prove_conditions(2, MapKind::GMap, {0, 2}, 2, 10);
}
TEST(ProofSlow, Thm1And2_2OMaps_Labels12_Nodes2_Darts10) {
  prove_conditions(2, MapKind::OMap, {1, 2}, 2, 10);
}
