// Evaluator::combine_classes (evaluator.hpp): a program that is one fused affine combination of
// node values (program.hpp, Combine: Loop's edge mask) evaluated for many classes in one loop.
// Each class gets the operations of Evaluator::run on that instruction, in the same order (the
// offset, then acc = acc + w_i * value_i for each load), and the mass check of evaluate(), so the
// values are run's bit for bit (model/expr/tests/program_test.cpp); what is saved is the set-up,
// the dispatch and the calls per class. A class whose load finds no dart or no value, or whose mass
// is wrong, stops the loop: the caller evaluates that class on its own for its error.
#include <cmath>

#include "model/expr/evaluator.hpp"

namespace gmr::expr {

bool Evaluator::combines_node_values(const Program& p) {
  if (p.code.size() != 1 || p.code[0].op != Instruction::Op::Combine) return false;
  for (uint32_t k = 0; k < p.code[0].count; ++k) {
    const LoadRef& r = p.loads[p.code[0].index + k];
    if (r.variable || r.index != 0) return false;
  }
  return true;
}

namespace {

// A load of the combination with what it reads taken once: the link array of each step of its
// path, the field's slot and value tables, its weight.
struct Term {
  const Dart* step[LoadRef::kMaxPath];
  uint8_t length = 0;
  const uint32_t* slots = nullptr;
  size_t size = 0;
  const Vec3* values = nullptr;
  double weight = 1;
};

}  // namespace

size_t Evaluator::combine_classes(const Program& p, const Dart* nodes, size_t n, ValueType target,
                                  std::vector<Vec3>& out) const {
  if (!memo_on_ || !combines_node_values(p)) return 0;
  const Instruction& ins = p.code[0];
  const LoadRef* const loads = p.loads.data() + ins.index;
  const Dart cap = g_.capacity();
  // Points and vectors (not scalars): every term's fourth lane is its mass, 1 or 0, so the
  // combination's mass is the same sum for every class, computed once as run computes it.
  std::vector<Term> terms(ins.count);
  double mass = ins.value[3];
  bool affine = true;
  for (uint32_t k = 0; k < ins.count; ++k) {
    const LoadRef& r = loads[k];
    const HeldField& f = held_fields_[r.embedding];
    Term& term = terms[k];
    term = {.step = {},
            .length = r.length,
            .slots = f.slots,
            .size = f.size,
            .values = f.values,
            .weight = r.weight};
    for (uint8_t s = 0; s < r.length; ++s) term.step[s] = held_links_[r.path[s]];
    affine = affine && f.type != ValueType::Scalar;
    mass = mass + (f.type == ValueType::Point ? 1.0 : 0.0) * r.weight;
  }
  if (!affine) return combine_classes_in_lanes(p, nodes, n, target, out);
  if ((target == ValueType::Point && std::fabs(mass - 1.0) > 1e-9) ||
      (target == ValueType::Vector && std::fabs(mass) > 1e-9))
    return 0;
  // The values written in place (no call in the loop: the sums stay in registers); cut back to the
  // classes done when one fails.
  const size_t first = out.size();
  out.resize(first + n);
  Vec3* const to = out.data() + first;
  for (size_t j = 0; j < n; ++j) {
    double x = ins.value[0], y = ins.value[1], z = ins.value[2];
    bool found = nodes[j] < cap;
    for (const Term& term : terms) {
      if (!found) break;
      Dart d = nodes[j];
      for (uint8_t s = 0; s < term.length; ++s) d = term.step[s][d];
      found = d < term.size && term.slots[d] != Embedding<Vec3>::kNoValue;
      if (!found) break;
      const Vec3& v = term.values[term.slots[d]];
      x = x + v[0] * term.weight;
      y = y + v[1] * term.weight;
      z = z + v[2] * term.weight;
    }
    if (!found) {
      out.resize(first + j);
      return j;
    }
    to[j] = {x, y, z};
  }
  return n;
}

// combine_classes with the four lanes of run (scalar fields among the terms).
size_t Evaluator::combine_classes_in_lanes(const Program& p, const Dart* nodes, size_t n,
                                           ValueType target, std::vector<Vec3>& out) const {
  const Instruction& ins = p.code[0];
  const LoadRef* const loads = p.loads.data() + ins.index;
  const Dart cap = g_.capacity();
  for (size_t j = 0; j < n; ++j) {
    Val acc{ins.value[0], ins.value[1], ins.value[2], ins.value[3]};
    for (uint32_t k = 0; k < ins.count; ++k) {
      const LoadRef& r = loads[k];
      Dart d = nodes[j];
      if (d >= cap) return j;
      for (uint8_t s = 0; s < r.length; ++s) d = held_links_[r.path[s]][d];
      const HeldField& f = held_fields_[r.embedding];
      if (d >= f.size || f.slots[d] == Embedding<Vec3>::kNoValue) return j;
      acc = ops::add(acc, ops::scale(from_storage(f.values[f.slots[d]], f.type), r.weight));
    }
    if ((target == ValueType::Point && std::fabs(acc.w - 1.0) > 1e-9) ||
        (target == ValueType::Vector && std::fabs(acc.w) > 1e-9))
      return j;
    out.push_back(to_storage(acc));
  }
  return n;
}

}  // namespace gmr::expr
