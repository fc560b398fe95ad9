// Larger bounds of the concrete-rule proofs (label slow; proofs/README.md for times).
#include "proofs/bounded.hpp"

using namespace gmr;
using namespace gmr::proofs;

// All three labels of 2-G-maps: 2 nodes, labels 0, 1, 2 (123967 rules), 4 darts.
TEST(ProofSlow, Thm1To3_2GMaps_Labels012_Nodes2_Darts4) { prove_conditions(2, MapKind::GMap, {0, 1, 2}, 2, 4); }

// Theorem 2 on 1-G-maps: 3 nodes, label 0, 8 darts.
TEST(ProofSlow, Thm2_1GMaps_Label0_Nodes3_Darts8) { prove_conditions(1, MapKind::GMap, {0}, 3, 8); }

// The cycle pair (0,2), 2 nodes, 8 darts.
TEST(ProofSlow, Thm3_2GMaps_Labels02_Nodes2_Darts8) { prove_conditions(2, MapKind::GMap, {0, 2}, 2, 8); }

// O-maps, 2 nodes, labels 1 and 2, 8 darts.
TEST(ProofSlow, Thm1And2_2OMaps_Labels12_Nodes2_Darts8) { prove_conditions(2, MapKind::OMap, {1, 2}, 2, 8); }
