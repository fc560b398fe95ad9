// The defining property of the scheme engine: applying a scheme with the engine gives
// the same G-map, with the corresponding comatch, as instantiating it on the hook orbit and
// applying the concrete rule by DPO (model/dpo.hpp, categorical construction of `rewrite::apply`).
// The DPO side computes its own match: the hook instances are anchored on the hook orbit (Alg. 5
// of model/orbit.hpp for the other hooks) and propagated along the instantiated L by
// anchored_match (model/match.hpp); the gluing condition is checked by dangling_arcs.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "model/core/orbit.hpp"
#include "model/graph/dgraph.hpp"
#include "model/rewrite/dpo.hpp"
#include "model/rewrite/match.hpp"
#include "model/scheme/scheme_engine.hpp"
#include "model/scheme/scheme_instantiation.hpp"

namespace gmr::testing {
using graph::DGraph;
using graph::Node;
using graph::to_dgraph;
using rewrite::anchored_match;
using rewrite::kNoNode;
using rewrite::MapDerivation;
using rewrite::Match;
using rewrite::Rule;
using scheme::OrbitGraph;
using scheme::RuleScheme;

struct EngineVsDpo {
  bool engine_applied = false;
  bool dpo_applied = false;
  std::string problem;  // empty when both agree
  Map result{0};        // the engine's result (when applied)
};

inline EngineVsDpo compare_engine_dpo(const Map& g, const RuleScheme& s,
                                      const std::vector<Dart>& hooks) {
  EngineVsDpo out;
  auto [h, a] = scheme::apply(scheme::SchemeEngine(s), std::as_const(g), hooks);
  out.engine_applied = a.applied;
  // DPO side.
  const OrbitGraph O = hook_orbit_graph(g, s, hooks.empty() ? 0 : hooks[0]);
  const size_t sz = O.size();
  const Rule r = instantiate_rule(s, O);
  const DGraph dg = to_dgraph(g);
  const auto darts = g.darts();
  std::vector<Node> node_of(g.capacity(), kNoNode);
  for (size_t k = 0; k < darts.size(); ++k) node_of[darts[k]] = Node(static_cast<uint32_t>(k));
  std::vector<std::pair<Node, Node>> anchors;
  bool iso_ok = true;
  const auto hook_nodes = s.hook_nodes();
  for (size_t c = 0; c < hook_nodes.size(); ++c) {
    const uint32_t hv = hook_nodes[c];
    if (c == 0) {
      for (uint32_t b = 0; b < sz; ++b)
        anchors.push_back({Node(static_cast<uint32_t>(hv * sz + b)), node_of[O.darts[b]]});
      continue;
    }
    auto iso = orbit_isomorphism(g, s.left.nodes[hook_nodes[0]].label, hooks[0], g,
                                 s.left.nodes[hv].label, hooks[c]);
    if (!iso) {
      iso_ok = false;
      break;
    }
    std::vector<Dart> img(g.capacity(), kNoDart);
    for (auto [x, y] : *iso) img[x] = y;
    for (uint32_t b = 0; b < sz; ++b)
      anchors.push_back({Node(static_cast<uint32_t>(hv * sz + b)), node_of[img[O.darts[b]]]});
  }
  std::optional<Match> m;
  if (iso_ok) m = anchored_match(r.left(), dg, anchors);
  if (m && !satisfies_gluing(r, dg, *m)) m.reset();
  out.dpo_applied = m.has_value();
  if (out.engine_applied != out.dpo_applied) {
    out.problem = std::string("engine ") + (a.applied ? "applied" : "refused (" + a.why + ")") +
                  ", DPO " + (out.dpo_applied ? "applied" : "refused");
    return out;
  }
  if (!a.applied) return out;
  std::vector<Dart> match;
  for (Node v : m->node) match.push_back(darts[v.index()]);
  const MapDerivation md = rewrite::apply(r, g, match, rewrite::Construction::Categorical);
  // phi: engine result -> DPO result.
  std::vector<Dart> phi(h.capacity(), kNoDart);
  auto assign = [&](Dart x, Dart y) {
    if (phi[x] != kNoDart && phi[x] != y)
      out.problem = "dart " + std::to_string(x) + " corresponds to two darts";
    phi[x] = y;
  };
  for (Dart x : darts)
    if (h.alive(x) && md.g_to_h[x] != kNoDart) assign(x, md.g_to_h[x]);
  for (uint32_t v = 0; v < s.right.size(); ++v)
    for (uint32_t b = 0; b < sz; ++b) assign(a.comatch_at(v, b), md.comatch[v * sz + b]);
  if (!out.problem.empty()) return out;
  if (h.size() != md.H.size()) {
    out.problem =
        "sizes differ: engine " + std::to_string(h.size()) + ", DPO " + std::to_string(md.H.size());
    return out;
  }
  std::vector<bool> hit(md.H.capacity(), false);
  h.for_each_dart([&](Dart x) {
    if (!out.problem.empty()) return;
    if (phi[x] == kNoDart || hit[phi[x]]) {
      out.problem = "dart " + std::to_string(x) + " has no (or a shared) counterpart";
      return;
    }
    hit[phi[x]] = true;
    for (int i = 0; i <= h.dimension(); ++i)
      if (phi[h.alpha(i, x)] != md.H.alpha(i, phi[x]))
        out.problem = "alpha_" + std::to_string(i) + " of dart " + std::to_string(x) + " differs";
  });
  out.result = std::move(h);
  return out;
}

}  // namespace gmr::testing
