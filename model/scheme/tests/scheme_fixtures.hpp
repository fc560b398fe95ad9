// Small rule schemes built in code for the model's unit tests (the library of operations lives in
// tools/data/rules/ as gmr.rule files; these are the thesis' reference schemes (thesis Ch. 6)
// and ch3-4 §6).
#pragma once
#include "model/scheme/rule_scheme.hpp"

namespace gmr::fixtures {
using scheme::RuleScheme;

inline OrbitType ot(const char* s) { return OrbitType::parse(s); }

// F9 / Fig. 6.15: quad subdivision (Catmull–Clark topology) on <0,1,2>.
inline RuleScheme quad_subdivision() {
  RuleScheme r;
  r.name = "quad";
  r.dimension = 2;
  r.orbit = ot("<0,1,2>");
  r.left.add_node("n0", ot("<0,1,2>"));
  r.right.add_node("n0", ot("<_,1,2>"));
  r.right.add_node("n1", ot("<_,_,2>"));
  r.right.add_node("n2", ot("<2,_,_>"));
  r.right.add_node("n3", ot("<2,1,_>"));
  r.right.add_arc("n0", "n1", 0);
  r.right.add_arc("n1", "n2", 1);
  r.right.add_arc("n2", "n3", 0);
  r.hooks = {"n0"};
  return r;
}

// F11 / Fig. 6.11b: vertex insertion on <0,2>.
inline RuleScheme vertex_insertion() {
  RuleScheme r;
  r.name = "vertex_insertion";
  r.dimension = 2;
  r.orbit = ot("<0,2>");
  r.left.add_node("n0", ot("<0,2>"));
  r.right.add_node("n0", ot("<_,2>"));
  r.right.add_node("n1", ot("<1,2>"));
  r.right.add_arc("n0", "n1", 0);
  r.hooks = {"n0"};
  return r;
}

// F5: 2-sewing of two 2-free edges, two hooks on <0>.
inline RuleScheme sew2() {
  RuleScheme r;
  r.name = "sew2";
  r.dimension = 2;
  r.orbit = ot("<0>");
  r.left.add_node("n0", ot("<0>"));
  r.left.add_node("n1", ot("<0>"));
  r.left.add_arc("n0", "n0", 2);
  r.left.add_arc("n1", "n1", 2);
  r.right.add_node("n0", ot("<0>"));
  r.right.add_node("n1", ot("<0>"));
  r.right.add_arc("n0", "n1", 2);
  r.hooks = {"n0", "n1"};
  return r;
}

}  // namespace gmr::fixtures
