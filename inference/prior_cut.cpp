#include "inference/prior_cut.hpp"

namespace gmr::inference {

size_t cut_prior_loops(JointGraph& j, DimMask dims) {
  size_t cut = 0;
  for (uint32_t x = 0; x < j.size(); ++x) {
    if (j.side(x) != Side::L) continue;
    const uint32_t y = j.nbr(x, kKappa);
    if (y == kUndefined) continue;  // not preserved
    for (int d = 0; d <= j.dimension(); ++d) {
      if (!((dims >> d) & 1u) || j.nbr(x, d) != x || j.nbr(y, d) != y) continue;
      j.set_nbr(x, d, kUndefined);
      j.set_nbr(y, d, kUndefined);
      ++cut;
    }
  }
  return cut;
}

}  // namespace gmr::inference
