// Shared helpers of the inference tests: data paths, and the exact check that a fold instantiates
// back to its joint graph (thesis Alg. 6 soundness: ι(P, J<o>(a)) = J with (b,v) ↦ darts[v][b]).
#pragma once
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "inference/fold.hpp"
#include "inference/joint_graph.hpp"
#include "model/scheme/scheme_instantiation.hpp"

namespace gmr::inference::test {

inline std::string source_dir() {
  const char* s = std::getenv("GMR_SOURCE_DIR");
  return s ? s : ".";
}
inline std::string data(const std::string& name) { return source_dir() + "/inference/tests/data/" + name; }
inline std::string rule_file(const std::string& name) { return source_dir() + "/tools/data/rules/" + name + ".json"; }

// Instantiates every side of the fold (κ arcs included, as label n+1) on its hook orbit and checks,
// dart by dart and dimension by dimension, that the instantiation is J under (b,v) ↦ darts[v][b].
inline ::testing::AssertionResult instantiates_back(const FoldResult& f, const JointGraph& j) {
  if (!f.ok()) return ::testing::AssertionFailure() << "fold failed: " << f.failure.message;
  const int n = j.dimension();
  GraphScheme s;
  for (uint32_t k = 0; k < f.nodes.size(); ++k) s.add_node(node_name(k), f.nodes[k].label);
  for (const auto& e : f.arcs) s.arcs.push_back({e.a, e.b, e.dim == kKappa ? n + 1 : e.dim});
  const InstantiatedGraph inst = instantiate(s, f.hook_orbit);
  std::vector<uint32_t> node_to_dart(inst.graph.num_nodes(), kUndefined);
  size_t bound = 0;
  for (uint32_t v = 0; v < f.nodes.size(); ++v)
    for (uint32_t b = 0; b < f.hook_orbit.size(); ++b) {
      node_to_dart[inst.at(v, b)] = f.nodes[v].darts[b];
      ++bound;
    }
  if (bound != j.size()) return ::testing::AssertionFailure() << bound << " instantiated darts for " << j.size() << " darts";
  for (Node u = 0; u < inst.graph.num_nodes(); ++u) {
    const uint32_t x = node_to_dart[u];
    for (int d = 0; d <= n + 1; ++d) {
      const auto succ = inst.graph.successors(u, d);
      const uint32_t want = j.nbr(x, d == n + 1 ? kKappa : d);
      if (want == kUndefined ? !succ.empty() : (succ.size() != 1 || node_to_dart[succ[0]] != want))
        return ::testing::AssertionFailure() << "dart " << j.describe(x) << ", dimension " << d << ": instantiation has "
                                             << succ.size() << " neighbour(s), J has "
                                             << (want == kUndefined ? "none" : j.describe(want));
    }
  }
  return ::testing::AssertionSuccess();
}

}  // namespace gmr::inference::test
