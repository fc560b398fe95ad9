// Verification of a fold by instantiation (thesis App. C, soundness: ι(P, J<o>(a)) = J with
// (b,v) ↦ darts[v][b]). Independent of Algorithm 6: the folded scheme (κ arcs as one more label)
// is instantiated on the hook orbit by the model's instantiation (Defs. 88–89), and the result is
// compared with J dart by dart and dimension by dimension. Used by the tests and the property tests
// ("fold then instantiate gives back the input").
#pragma once
#include <string>

#include "inference/fold.hpp"

namespace gmr::inference {

// "" when the instantiation of the successful fold `f` is J exactly, else the first difference.
std::string instantiation_mismatch(const FoldResult& f, const JointGraph& j);

}  // namespace gmr::inference
