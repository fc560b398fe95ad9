#include "tools/cli/inference_args.hpp"

#include <sstream>

#include "model/core/error.hpp"

namespace gmr::cli {


using namespace gmr::inference;

OrbitType parse_orbit_option(const std::string& text, const std::string& option) {
  OrbitType o;
  try {
    o = OrbitType::parse(text);
  } catch (const Error& e) {
    throw Error(ErrorCode::Usage, e.message(), option);
  }
  if (o.has_hole()) throw Error(ErrorCode::Usage, "an inference orbit type has no `_`", option);
  return o;
}

DimMask parse_dimension_list(const std::string& text, int n, const std::string& option) {
  DimMask m = 0;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    if (item.empty()) continue;
    size_t used = 0;
    int d = -1;
    try {
      d = std::stoi(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != item.size() || d < 0 || d > n)
      throw Error(ErrorCode::Usage, "\"" + item + "\" is not a dimension in 0.." + std::to_string(n), option);
    m |= DimMask(1) << d;
  }
  return m;
}

static nlohmann::ordered_json dim_json(int d) {
  if (d == kKappa) return "κ";
  if (d == kNoDimension) return nullptr;
  return d;
}

nlohmann::ordered_json failure_to_json(const FoldFailure& f, const JointGraph& j) {
  nlohmann::ordered_json out;
  out["kind"] = to_string(f.kind);
  out["node"] = f.node == inference::kNoFoldNode ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(node_name(f.node));
  out["dimension"] = dim_json(f.dim);
  if (f.position >= 0) out["position"] = f.position;
  nlohmann::ordered_json darts = nlohmann::ordered_json::array();
  for (uint32_t x : f.darts) darts.push_back(x == kUndefined ? "undefined" : j.describe(x));
  out["darts"] = darts;
  out["message"] = f.message;
  return out;
}

nlohmann::ordered_json fold_to_json(const FoldResult& r, const JointGraph& j) {
  nlohmann::ordered_json out;
  out["orbit"] = r.orbit.str();
  out["dart"] = j.describe(r.start);
  out["folded"] = r.ok();
  if (!r.ok()) {
    out["failure"] = failure_to_json(r.failure, j);
    return out;
  }
  nlohmann::ordered_json nodes = nlohmann::ordered_json::array();
  for (uint32_t k = 0; k < r.nodes.size(); ++k) {
    nlohmann::ordered_json darts = nlohmann::ordered_json::array();
    for (uint32_t x : r.nodes[k].darts) darts.push_back(j.origin(x));
    nlohmann::ordered_json n{{"name", node_name(k)}, {"orbit", r.nodes[k].label.str()}};
    if (j.has_after()) n["side"] = to_string(r.nodes[k].side);
    n["darts"] = darts;
    nodes.push_back(n);
  }
  out["nodes"] = nodes;
  nlohmann::ordered_json arcs = nlohmann::ordered_json::array();
  for (const auto& e : r.arcs)
    arcs.push_back({{"nodes", {node_name(e.a), node_name(e.b)}}, {"label", dim_json(e.dim)}});
  out["arcs"] = arcs;
  return out;
}

}  // namespace gmr::cli
