// Options shared by `gmr fold` and `gmr infer` (inference/).
#pragma once
#include <string>

#include "inference/fold.hpp"
#include "model/core/orbit_type.hpp"

namespace gmr::cli {

// An orbit type without `_` ("<0,2>", "<>"); Error(Usage) at `option` otherwise.
OrbitType parse_orbit_option(const std::string& text, const std::string& option);
// "0,2" -> mask of dimensions in 0..n; "" -> 0.
DimMask parse_dimension_list(const std::string& text, int n, const std::string& option);

}  // namespace gmr::cli
