// Text and JSON of the results of topological folding (fold.hpp) and of the inference driver
// (infer.hpp), the one writer of `gmr fold` and `gmr infer` (docs/inference.md). Darts are named
// by the joint graph (JointGraph::describe), nodes "n0", "n1", ... (node_name).
#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "inference/fold.hpp"
#include "inference/infer.hpp"

namespace gmr::inference {

// Text of a fold: the orbit type and start, then one line per node ("n3 <2,1> L") and per arc, or
// the failure.
std::string to_text(const FoldResult& f, const JointGraph& j);
// A fold as JSON: "orbit", "dart", "folded", then "nodes"/"arcs" or "failure".
nlohmann::ordered_json to_json(const FoldResult& f, const JointGraph& j);
// A fold failure as JSON: "kind", "node", "dimension", "position" (when set), "darts", "message".
nlohmann::ordered_json to_json(const FoldFailure& f, const JointGraph& j);

// The summary table of an inference (one line per attempt), then the count of rules inferred.
std::string to_text(const InferenceResult& r);

}  // namespace gmr::inference
