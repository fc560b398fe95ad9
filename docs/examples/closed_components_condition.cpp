// Worked example of a condition plug-in for `gmr validate-condition` (docs/verify.md).
//
// The condition "closed components": every node of L and of R is the source and the target of
// exactly one i-arc for every label of the model, and every i-arc of an involutive label has its
// reverse on its side. A rule satisfying it rewrites whole connected components of a map into
// components that are closed under every label (the style of the early sufficient conditions).
// The validation shows that on 1-G-maps and 2-O-maps (rules of at most 2 nodes, maps of at most
// 4 darts) it is sound but far from complete: it rejects every rule that touches only part of a
// component, the smallest being the identity on one node with no arc. It does not look at the
// cycle constraint, so it is no condition for 2-G-maps in general; rules of 2 nodes cannot show it
// (two involutions of at most two darts always commute).
//
// Build and run:
//   c++ -std=c++20 -shared -fPIC -I<gmr source> closed_components_condition.cpp -o libclosed.so
//   gmr validate-condition --plugin ./libclosed.so --labels 0,1 --max-nodes 2 --bound 4
#include "checker/smt/condition_api.hpp"

namespace {
using namespace gmr::condition;

bool closed(const RuleView& r, Side s) {
  const Graph& g = r.side(s);
  for (unsigned v = 0; v < g.nodes.size(); ++v)
    for (int i : r.labels()) {
      const auto out = r.out_arcs(s, v, i);
      if (out.size() != 1 || r.in_arcs(s, v, i).size() != 1) return false;
      const Arc& a = g.arcs[out[0]];
      if (r.involutive(i) && !r.find_arc(s, a.target, a.source, i)) return false;
    }
  return true;
}

bool closed_components(const RuleView& r) {
  return closed(r, Side::Left) && closed(r, Side::Right);
}
}  // namespace

GMR_CONDITION_PLUGIN("closed-components",
                     "every node of L and R has one i-arc out and in per label, involutions",
                     closed_components)
