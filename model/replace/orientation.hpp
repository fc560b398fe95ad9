// Orientation classes of a G-map (Damiand & Nivoliers 2022 use oriented 3-maps; a G-map stores
// no orientation). In each connected component, D+ is the class of the 2-colouring flipped by every
// alpha_i that contains the component's smallest dart; it exists iff the component is orientable
// (a free dart, an i-loop, makes no conflict: it is not a link). This is the oriented mode's
// convention: patterns and targets are compared with that D+ (see docs/query-replace.md).
#pragma once
#include <cstdint>
#include <vector>

#include "model/core/map.hpp"

namespace gmr::replace {

// positive[d] = 1 for darts of D+, indexed by dart. Throws Error(InvalidMap) naming a dart of a
// non-orientable component.
std::vector<uint8_t> orientation_classes(const Map& g);

}  // namespace gmr::replace
