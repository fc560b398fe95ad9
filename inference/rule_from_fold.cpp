#include "inference/rule_from_fold.hpp"

#include "model/core/error.hpp"

namespace gmr::inference {

using namespace gmr::checker;
using namespace gmr::scheme;

const char* to_string(RuleVerdict v) {
  switch (v) {
    case RuleVerdict::Accepted:
      return "accepted";
    case RuleVerdict::NoHook:
      return "no hook";
    case RuleVerdict::Inconsistent:
      return "rejected by the checker";
  }
  return "?";
}

namespace {

// Removes the explicit d-loops (d in mask) present on both copies of a preserved node.
void cut_preserved_loops(RuleScheme& s, DimMask mask) {
  auto is_loop_at = [](const SchemeArc& e, uint32_t v, DimMask m) {
    return e.a == v && e.b == v && ((m >> e.dim) & 1u);
  };
  for (uint32_t v = 0; v < s.left.size(); ++v) {
    const auto w = s.right_of(v);
    if (!w) continue;
    for (int d = 0; d <= s.dimension; ++d) {
      if (!((mask >> d) & 1u)) continue;
      const DimMask one = DimMask(1) << d;
      bool in_l = false, in_r = false;
      for (const auto& e : s.left.arcs) in_l = in_l || is_loop_at(e, v, one);
      for (const auto& e : s.right.arcs) in_r = in_r || is_loop_at(e, *w, one);
      if (!in_l || !in_r) continue;
      std::erase_if(s.left.arcs, [&](const SchemeArc& e) { return is_loop_at(e, v, one); });
      std::erase_if(s.right.arcs, [&](const SchemeArc& e) { return is_loop_at(e, *w, one); });
    }
  }
}

}  // namespace

InferredRule rule_from_fold(const FoldResult& f, const JointGraph& j, const std::string& name,
                            const RuleOptions& opt) {
  if (!f.ok()) throw Error(ErrorCode::Usage, "the fold failed: " + f.failure.message);
  InferredRule out;
  out.orbit = f.orbit;
  out.start = j.origin(f.start);
  RuleScheme& s = out.scheme;
  s.name = name;
  s.dimension = j.dimension();
  s.orbit = f.orbit;
  s.description = "Inferred by topological folding (thesis Alg. 6) on " + f.orbit.str() +
                  " from before dart " + std::to_string(out.start) + ".";
  const size_t k = f.nodes.size();
  std::vector<uint32_t> kappa(k, kNoFoldNode);
  for (const auto& e : f.arcs)
    if (e.dim == kKappa) {
      kappa[e.a] = e.b;
      kappa[e.b] = e.a;
    }
  std::vector<uint32_t> local(k, kNoFoldNode);  // index on its side
  auto darts_of = [&](uint32_t m) {
    std::vector<Dart> d;
    for (uint32_t x : f.nodes[m].darts) d.push_back(j.origin(x));
    return d;
  };
  uint32_t next = 0;
  std::vector<std::string> names(k);
  for (uint32_t m = 0; m < k; ++m)
    if (f.nodes[m].side == Side::L) {
      names[m] = node_name(next++);
      local[m] = s.left.add_node(names[m], f.nodes[m].label);
      out.left_darts.push_back(darts_of(m));
    }
  for (uint32_t m = 0; m < k; ++m)
    if (f.nodes[m].side == Side::R) {
      names[m] = kappa[m] != kNoFoldNode ? names[kappa[m]] : node_name(next++);
      local[m] = s.right.add_node(names[m], f.nodes[m].label);
      out.right_darts.push_back(darts_of(m));
    }
  for (const auto& e : f.arcs) {
    if (e.dim == kKappa) continue;
    GraphScheme& g = f.nodes[e.a].side == Side::L ? s.left : s.right;
    g.arcs.push_back({local[e.a], local[e.b], e.dim});
  }
  if (opt.cut_loops) cut_preserved_loops(s, opt.cut_loops);
  // Hooks: one per L component.
  std::vector<uint32_t> comp;
  const size_t nc = s.left.components(comp);
  std::vector<uint32_t> hook(nc, kNoFoldNode);
  const uint32_t h = local[0];
  hook[comp[h]] = h;
  for (uint32_t v = 0; v < s.left.size(); ++v) {
    const OrbitType& label = s.left.nodes[v].label;
    if (label.has_hole()) continue;
    uint32_t& cur = hook[comp[v]];
    if (cur == kNoFoldNode || (cur != h && label == f.orbit && s.left.nodes[cur].label != f.orbit))
      cur = v;
  }
  s.hooks.push_back(s.left.nodes[h].name);
  for (uint32_t v = 0; v < s.left.size(); ++v) {  // components in order of their first node
    const uint32_t c = comp[v];
    if (c == comp[h] || hook[c] == UINT32_MAX - 1) continue;
    if (hook[c] == kNoFoldNode) {
      out.verdict = RuleVerdict::NoHook;
      out.reason =
          "the L component of node " + s.left.nodes[v].name +
          " has no node with a full decoration (no `_`) to serve as its hook (thesis §7.3.1)";
      return out;
    }
    s.hooks.push_back(s.left.nodes[hook[c]].name);
    hook[c] = UINT32_MAX - 1;  // done
  }
  out.check = check_scheme(s);
  if (!out.check.ok()) {
    out.verdict = RuleVerdict::Inconsistent;
    std::string codes;
    for (const auto& d : out.check.diagnostics)
      if (d.severity == Severity::Error) {
        codes += (codes.empty() ? "" : "; ") + d.code + " " + d.side_str();
        for (const auto& nn : d.nodes) codes += " " + nn;
      }
    out.reason = "the scheme checker rejects it: " + codes;
  }
  return out;
}

}  // namespace gmr::inference
