// Prior-cut loops (thesis §7.3, inference parameters of Fig. 7.13): before folding, the d-loops of
// preserved darts are removed from the joint representation, for the chosen dimensions d, so that
// the inferred rule does not demand d-free cells on its preserved nodes (a free edge or a polygon
// given as the example would otherwise restrict the rule to free cells).
//
// Reading chosen here (the thesis does not say which loops of a preserved dart): a loop is cut only
// when the dart has it on both sides — x –d– x in G and κ(x) –d– κ(x) in H — so that the rule
// leaves the d-links of those darts as they are; a d-loop the operation creates or removes is part
// of what it does and stays. A cut slot becomes undefined, which folding reads like a selection
// cut (all or none per node, docs/inference.md). Posterior-cut loops (rule_from_fold.hpp) remove
// the same loops from the inferred scheme instead; excluded loops (relabeling.hpp) only decide how
// a loop is read.
#pragma once
#include <cstddef>

#include "inference/joint_graph.hpp"
#include "model/core/orbit_type.hpp"

namespace gmr::inference {

// Cuts the loops of the dimensions in `dims` as above; returns the number of darts of L cut (per
// dimension).
size_t cut_prior_loops(JointGraph& j, DimMask dims);

}  // namespace gmr::inference
