// Values of the expression language and their operations (docs/embeddings.md, "Types"), shared
// by the tree interpreter (evaluator.cpp) and the compiled programs (program.cpp folds constants
// with them, so a folded value is the one the evaluation computes).
//
// A value is homogeneous: (x, y, z, w) with w the mass of an affine value (1 for a point, 0 for a
// vector; type.hpp); a scalar is x, a colour (x, y, z).
#pragma once
#include <cmath>
#include <cstddef>

#include "model/expr/ast.hpp"

namespace gmr::expr {

struct Val {
  double x = 0, y = 0, z = 0, w = 0;
};

namespace ops {
inline Val add(const Val& a, const Val& b) { return {a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w}; }
}  // namespace ops

// The multiset of an aggregate's members kept as all that middle, sum and count read of it: the
// sum of the values in the order they are met, and their number (the members are not stored).
struct MemberSum {
  Val sum;
  size_t n = 0;
  void push_back(const Val& v) {
    sum = ops::add(sum, v);
    ++n;
  }
};

namespace ops {
inline Val sub(const Val& a, const Val& b) { return {a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w}; }
inline Val scale(const Val& a, double k) { return {a.x * k, a.y * k, a.z * k, a.w * k}; }
inline Val neg(const Val& a) { return scale(a, -1.0); }
inline Val divide(const Val& a, double k) {
  return scale(a, 1.0 / k);
}  // k != 0 (checked by the caller)
inline Val make(Function f, const Val& x, const Val& y, const Val& z) {
  return {x.x, y.x, z.x, f == Function::Point ? 1.0 : 0.0};
}
inline Val cos(const Val& a) { return {std::cos(a.x), 0, 0, 0}; }
inline Val sin(const Val& a) { return {std::sin(a.x), 0, 0, 0}; }
inline Val abs(const Val& a) { return {std::fabs(a.x), 0, 0, 0}; }
inline Val sqrt(const Val& a) {
  return {std::sqrt(a.x), 0, 0, 0};
}  // a.x >= 0 (checked by the caller)
inline Val dot(const Val& a, const Val& b) { return {a.x * b.x + a.y * b.y + a.z * b.z, 0, 0, 0}; }
inline Val cross(const Val& a, const Val& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x, 0};
}
inline Val norm(const Val& a) { return {std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z), 0, 0, 0}; }
inline Val clamp(const Val& a) {
  auto c = [](double v) { return v < 0 ? 0.0 : v > 1 ? 1.0 : v; };
  return {c(a.x), c(a.y), c(a.z), 0};
}
// middle, sum or count of n values summing to acc (middle: n > 0, checked by the caller).
inline Val finish_aggregate(Function f, const Val& acc, size_t n) {
  if (f == Function::Count) return {static_cast<double>(n), 0, 0, 0};
  if (f == Function::Sum) return acc;
  return scale(acc, 1.0 / static_cast<double>(n));
}
}  // namespace ops

}  // namespace gmr::expr
