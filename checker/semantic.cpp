#include "checker/semantic.hpp"

#include "model/rewrite/dpo.hpp"
#include "model/core/error.hpp"

namespace gmr::checker {
using namespace gmr::graph;
using namespace gmr::rewrite;

std::string SemanticWitness::describe(const Rule& r, const MapFamily& f) const {
  const Map& g = f.maps[map_index];
  std::string s = "map #" + std::to_string(map_index) + " (" + std::to_string(g.size()) + " darts;";
  for (int i = g.lowest_dim(); i <= g.dimension(); ++i) {
    s += std::string(" ") + (g.is_omap() ? "beta" : "alpha") + std::to_string(i) + "=[";
    for (Dart d = 0; d < g.capacity(); ++d) s += (d ? "," : "") + std::to_string(g.alpha(i, d));
    s += "]";
  }
  s += "), match";
  for (Node v : r.left().nodes()) s += " " + r.left().name(v) + "->" + std::to_string(graph::dart_of(match.node[v]));
  s += "; H breaks:";
  for (size_t k = 0; k < violations.size() && k < 3; ++k) s += " " + violations[k].describe(H) + ";";
  return s;
}

SemanticVerdict semantic_verdict(const Rule& r, const MapFamily& f, bool stop_at_first) {
  if (r.kind() != f.kind || r.dimension() != f.n)
    throw Error(ErrorCode::Usage, "the rule and the map family have different models", "rule " + r.name());
  SemanticVerdict v;
  for (size_t k = 0; k < f.graphs.size(); ++k) {
    const DGraph& G = f.graphs[k];
    bool stop = false;
    for_each_match(r.left(), G, [&](const Match& m) {
      ++v.matches;
      if (!satisfies_gluing(r, G, m)) return true;
      ++v.applications;
      Derivation d = derive_in_place(r, G, m);
      auto viol = check_gmap_constraints(d.H, f.n, f.kind);
      if (viol.empty()) return true;
      if (v.preserves) {
        v.preserves = false;
        v.witness = SemanticWitness{k, m, std::move(d.H), std::move(viol)};
      }
      if (stop_at_first) stop = true;
      return !stop;
    });
    if (stop) break;
  }
  return v;
}

}  // namespace gmr::checker
