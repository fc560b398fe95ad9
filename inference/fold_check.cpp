#include "inference/fold_check.hpp"

#include "model/scheme/scheme_instantiation.hpp"

namespace gmr::inference {

using namespace gmr::graph;
using namespace gmr::scheme;

std::string instantiation_mismatch(const FoldResult& f, const JointGraph& j) {
  if (!f.ok()) return "the fold failed: " + f.failure.message;
  const int n = j.dimension();
  GraphScheme s;
  for (uint32_t k = 0; k < f.nodes.size(); ++k) s.add_node(node_name(k), f.nodes[k].label);
  for (const auto& e : f.arcs) s.arcs.push_back({e.a, e.b, e.dim == kKappa ? n + 1 : e.dim});
  const InstantiatedGraph inst = instantiate_graph(s, f.hook_orbit);
  HandleVector<Node, uint32_t> node_to_dart(inst.graph.num_nodes(), kUndefined);
  size_t bound = 0;
  for (uint32_t v = 0; v < f.nodes.size(); ++v)
    for (uint32_t b = 0; b < f.hook_orbit.size(); ++b) {
      node_to_dart[inst.at(v, b)] = f.nodes[v].darts[b];
      ++bound;
    }
  if (bound != j.size())
    return std::to_string(bound) + " instantiated darts for " + std::to_string(j.size()) + " darts";
  for (Node u : inst.graph.nodes()) {
    const uint32_t x = node_to_dart[u];
    for (int d = 0; d <= n + 1; ++d) {
      const auto succ = inst.graph.successors(u, d);
      const uint32_t want = j.nbr(x, d == n + 1 ? kKappa : d);
      const bool same =
          want == kUndefined ? succ.empty() : (succ.size() == 1 && node_to_dart[succ[0]] == want);
      if (!same)
        return "dart " + j.describe(x) + ", dimension " + dimension_text(d == n + 1 ? kKappa : d) +
               ": the instantiation has " + std::to_string(succ.size()) + " neighbour(s), J has " +
               (want == kUndefined ? std::string("none") : "dart " + j.describe(want));
    }
  }
  return {};
}

}  // namespace gmr::inference
