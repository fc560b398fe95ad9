#include "checker/semantic.hpp"

#include "model/core/error.hpp"
#include "model/rewrite/dpo.hpp"

namespace gmr::checker {
using namespace gmr::graph;
using namespace gmr::rewrite;

SemanticVerdict semantic_verdict(const Rule& r, const MapFamily& f, bool stop_at_first) {
  if (r.kind() != f.kind || r.dimension() != f.n)
    throw Error(ErrorCode::Usage, "the rule and the map family have different models",
                "rule " + r.name());
  SemanticVerdict v;
  for (size_t k = 0; k < f.graphs.size(); ++k) {
    const DGraph& G = f.graphs[k];
    bool stop = false;
    for_each_match(r.left(), G, [&](const Match& m) {
      ++v.matches;
      if (!satisfies_gluing(r, G, m)) return true;
      ++v.applications;
      Derivation d = derive(r, G, m, Construction::Rewriting);
      auto viol = check_map_constraints(d.H, f.n, f.kind);
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
