// Options and JSON shared by `gmr fold` and `gmr infer` (inference/).
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "inference/fold.hpp"
#include "model/core/orbit_type.hpp"

namespace gmr::cli {

// An orbit type without `_` ("<0,2>", "<>"); Error(Usage) at `option` otherwise.
OrbitType parse_orbit_option(const std::string& text, const std::string& option);
// "0,2" -> mask of dimensions in 0..n; "" -> 0.
DimMask parse_dimension_list(const std::string& text, int n, const std::string& option);
// A fold as JSON: "orbit", "dart", "folded", then "nodes"/"arcs" or "failure".
nlohmann::ordered_json fold_to_json(const inference::FoldResult& r, const inference::JointGraph& j);
nlohmann::ordered_json failure_to_json(const inference::FoldFailure& f, const inference::JointGraph& j);

}  // namespace gmr::cli
