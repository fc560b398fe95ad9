#include "inference/inference_format.hpp"

#include <iomanip>
#include <sstream>

namespace gmr::inference {

namespace {

// A label of the joint graph: a dimension, "κ", or null (none).
nlohmann::ordered_json dim_json(int d) {
  if (d == kKappa) return "κ";
  if (d == kNoDimension) return nullptr;
  return d;
}

}  // namespace

nlohmann::ordered_json to_json(const FoldFailure& f, const JointGraph& j) {
  nlohmann::ordered_json out;
  out["kind"] = to_string(f.kind);
  out["node"] = f.node == kNoFoldNode ? nlohmann::ordered_json(nullptr)
                                      : nlohmann::ordered_json(node_name(f.node));
  out["dimension"] = dim_json(f.dim);
  if (f.position >= 0) out["position"] = f.position;
  nlohmann::ordered_json darts = nlohmann::ordered_json::array();
  for (uint32_t x : f.darts) darts.push_back(x == kUndefined ? "undefined" : j.describe(x));
  out["darts"] = darts;
  out["message"] = f.message;
  return out;
}

nlohmann::ordered_json to_json(const FoldResult& r, const JointGraph& j) {
  nlohmann::ordered_json out;
  out["orbit"] = r.orbit.str();
  out["dart"] = j.describe(r.start);
  out["folded"] = r.ok();
  if (!r.ok()) {
    out["failure"] = to_json(r.failure, j);
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

std::string to_text(const FoldResult& f, const JointGraph& j) {
  std::ostringstream os;
  os << "fold on " << f.orbit.str() << " from dart " << j.describe(f.start) << ": ";
  if (!f.ok()) {
    os << to_string(f.failure.kind) << "\n  " << f.failure.message << "\n";
    return os.str();
  }
  os << f.nodes.size() << " nodes, hook orbit of " << f.hook_orbit.size() << " darts\n";
  for (uint32_t k = 0; k < f.nodes.size(); ++k)
    os << "  " << node_name(k) << " " << f.nodes[k].label.str()
       << (j.has_after() ? std::string(" ") + to_string(f.nodes[k].side) : "")
       << (k == 0 ? "  (hook)" : "") << "\n";
  for (const auto& e : f.arcs)
    os << "  " << node_name(e.a) << " -" << dimension_text(e.dim) << "- " << node_name(e.b) << "\n";
  return os.str();
}

std::string to_text(const InferenceResult& r) {
  std::ostringstream os;
  os << std::left << std::setw(12) << "orbit" << std::setw(14) << "start" << std::setw(5) << "L"
     << std::setw(5) << "R"
     << "outcome\n";
  for (const auto& a : r.attempts) {
    os << std::setw(12) << a.orbit.str() << std::setw(14) << a.start_text << std::setw(5)
       << a.left_nodes << std::setw(5) << a.right_nodes << to_string(a.outcome);
    if (a.outcome == AttemptOutcome::FoldFailed) os << ": " << to_string(a.failure.kind);
    if (a.outcome == AttemptOutcome::Accepted) os << " as rule " << a.rule;
    if (a.outcome == AttemptOutcome::Duplicate) os << " of rule " << a.rule;
    if (a.outcome == AttemptOutcome::Inconsistent || a.outcome == AttemptOutcome::NoHook)
      os << ": " << a.reason;
    os << "\n";
  }
  os << r.rules.size() << " rule(s) inferred";
  size_t dups = 0;
  for (size_t d : r.duplicates) dups += d;
  os << ", " << dups << " duplicate(s) merged";
  if (r.truncated) os << " (relabeling enumeration truncated at its limit)";
  os << "\n";
  return os.str();
}

}  // namespace gmr::inference
