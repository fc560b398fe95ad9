// Shared helpers of the inference tests: data paths, and the exact check that a fold instantiates
// back to its joint graph (thesis App. C soundness: ι(P, J<o>(a)) = J with (b,v) ↦ darts[v][b]).
#pragma once
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "inference/fold.hpp"
#include "inference/fold_check.hpp"
#include "inference/joint_graph.hpp"
#include "model/testing/source_tree.hpp"

namespace gmr::inference::test {

inline std::string source_dir() { return gmr::testing::source_path("."); }
// An orbit type in the papers' notation, e.g. ot("<0,_,2>").
inline OrbitType ot(const char* s) { return OrbitType::parse(s); }

inline std::string data(const std::string& name) {
  return source_dir() + "/inference/tests/data/" + name;
}
inline std::string rule_file(const std::string& name) {
  return source_dir() + "/tools/data/rules/" + name + ".json";
}

// The fold instantiates back to J exactly (fold_check.hpp).
inline ::testing::AssertionResult instantiates_back(const FoldResult& f, const JointGraph& j) {
  const std::string why = instantiation_mismatch(f, j);
  if (why.empty()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << why;
}

}  // namespace gmr::inference::test
