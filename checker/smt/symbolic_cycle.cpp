#include "checker/smt/symbolic_cycle.hpp"

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <string>

namespace gmr::smt {

namespace {
bool in(unsigned mask, int x) { return (mask >> x) & 1u; }
// The slots of mask among the first n, increasing.
std::vector<int> slots_of(unsigned mask, int n) {
  std::vector<int> slot;
  for (int x = 0; x < n; ++x)
    if (in(mask, x)) slot.push_back(x);
  return slot;
}
}  // namespace

SymbolicCycle::SymbolicCycle(const SymbolicRule& rule, std::vector<int> cycle_labels)
    : rule_(rule), labels_(std::move(cycle_labels)) {
  const unsigned masks = 1u << rule_.slots();
  ok_.push_back(rule_.ctx().bool_val(true));
  for (unsigned s = 1; s < masks; ++s)
    ok_.push_back(rule_.ctx().bool_const(("cycle_ok_" + std::to_string(s)).c_str()));
}

z3::expr SymbolicCycle::linked(int x, int y) const {
  z3::expr_vector any(rule_.ctx());
  for (bool right : {false, true})
    for (int l : labels_) {
      any.push_back(rule_.arc(right, l, x, y));
      any.push_back(rule_.arc(right, l, y, x));
    }
  return z3::mk_or(any);
}

z3::expr SymbolicCycle::component(unsigned mask) const {
  z3::expr_vector all(rule_.ctx());
  const int n = rule_.slots();
  int first = -1;
  for (int x = 0; x < n; ++x) {
    if (!in(mask, x)) continue;
    if (first < 0) first = x;
    all.push_back(rule_.exists(x));
    // Closed: no arc between S and the other slots.
    for (int y = 0; y < n; ++y)
      if (!in(mask, y)) all.push_back(!linked(x, y));
  }
  // Connected: every split of S into A (holding S's first slot) and S \ A has an arc across.
  for (unsigned a = 1; a < mask; ++a) {
    if ((a & mask) != a || !in(a, first)) continue;
    z3::expr_vector across(rule_.ctx());
    for (int x = 0; x < n; ++x)
      for (int y = 0; y < n; ++y)
        if (in(a, x) && in(mask & ~a, y)) across.push_back(linked(x, y));
    all.push_back(z3::mk_or(across));
  }
  return z3::mk_and(all);
}

z3::expr SymbolicCycle::untouched(int x, unsigned mask) const {
  z3::expr_vector all(rule_.ctx());
  all.push_back(!rule_.added(x));
  for (int l : labels_)
    for (int y = 0; y < rule_.slots(); ++y)
      if (in(mask, y)) all.push_back(!rule_.deleted_arc(l, x, y) && !rule_.added_arc(l, x, y));
  return z3::mk_and(all);
}

z3::expr_vector SymbolicCycle::axioms(const z3::expr& guard, const z3::expr& cycle_holds) const {
  z3::expr_vector out(rule_.ctx()), each(rule_.ctx());
  for (unsigned s = 1; s < ok_.size(); ++s) {
    const z3::expr c = component(s);
    each.push_back(z3::implies(c, ok_[s]));
    z3::expr_vector quiet(rule_.ctx());
    for (int x = 0; x < rule_.slots(); ++x)
      if (in(s, x)) quiet.push_back(untouched(x, s));
    out.push_back(z3::implies(c && z3::mk_and(quiet), ok_[s]));
  }
  out.push_back(z3::implies(guard, cycle_holds == z3::mk_and(each)));
  return out;
}

unsigned SymbolicCycle::mask_of(const std::vector<std::string>& nodes) const {
  unsigned mask = 0;
  for (const std::string& name : nodes) {
    const int x = name.size() == 1 ? name[0] - 'a' : -1;
    if (x < 0 || x >= rule_.slots())
      throw std::logic_error("node " + name + " is not a slot of the symbolic rule");
    mask |= 1u << x;
  }
  return mask;
}

z3::expr SymbolicCycle::lemma(const z3::model& m, unsigned mask, bool verdict) const {
  auto val = [&](const z3::expr& e) { return m.eval(e, true).is_true(); };
  // The pattern: the slots of mask in order, their statuses and the cycle-label arcs among them.
  std::vector<int> from;
  for (int x = 0; x < rule_.slots(); ++x)
    if (in(mask, x)) from.push_back(x);
  const size_t k = from.size();
  std::vector<int> status(k);  // 0 preserved, 1 deleted, 2 added: the family's order
  for (size_t i = 0; i < k; ++i)
    status[i] = val(rule_.preserved(from[i])) ? 0 : val(rule_.deleted(from[i])) ? 1 : 2;
  // Every injective placement i -> to[i] onto slots that keeps the status order along the slots.
  z3::expr_vector lemmas(rule_.ctx());
  std::vector<int> to;
  std::vector<bool> used(static_cast<size_t>(rule_.slots()), false);
  // With one cycle pair {i, j}, C_r is symmetric in i and j (Defs. 38-40 and the completions
  // treat both labels alike): the pattern with i and j swapped gets the same verdict.
  std::vector<int> image_label = labels_;
  std::function<void()> place = [&] {
    if (to.size() == k) {
      z3::expr_vector same(rule_.ctx());
      unsigned image = 0;
      for (size_t i = 0; i < k; ++i) {
        image |= 1u << to[i];
        same.push_back(rule_.in_left(to[i]) == rule_.ctx().bool_val(val(rule_.in_left(from[i]))));
        same.push_back(rule_.in_right(to[i]) == rule_.ctx().bool_val(val(rule_.in_right(from[i]))));
        for (size_t j = 0; j < k; ++j)
          for (bool right : {false, true})
            for (size_t l = 0; l < labels_.size(); ++l) {
              const z3::expr a = rule_.arc(right, image_label[l], to[i], to[j]);
              same.push_back(val(rule_.arc(right, labels_[l], from[i], from[j])) ? a : !a);
            }
      }
      lemmas.push_back(z3::implies(z3::mk_and(same), ok_[image] == rule_.ctx().bool_val(verdict)));
      return;
    }
    const size_t i = to.size();
    for (int y = 0; y < rule_.slots(); ++y) {
      if (used[y]) continue;
      bool ordered = true;  // slots below y hold no higher status, slots above no lower one
      for (size_t j = 0; j < i; ++j)
        if ((to[j] < y && status[j] > status[i]) || (to[j] > y && status[j] < status[i]))
          ordered = false;
      if (!ordered) continue;
      used[y] = true;
      to.push_back(y);
      place();
      to.pop_back();
      used[y] = false;
    }
  };
  place();
  if (labels_.size() == 2) {
    std::swap(image_label[0], image_label[1]);
    place();
  }
  return z3::mk_and(lemmas);
}

z3::expr_vector SymbolicCycle::table_lemmas(const CycleTable& table) const {
  // Each pattern is the cube that fixes every one of its variables.
  const size_t nl = table.labels.size();
  std::vector<PatternCube> exact;
  for (const ComponentPattern& p : table.patterns) {
    const size_t vars = pattern_variables(p.nodes(), nl);
    if (vars > 128) throw std::logic_error("table_lemmas: more than 128 pattern variables");
    PatternCube cube{p.nodes(), p.holds, {}, pattern_bits(p, nl)};
    for (size_t v = 0; v < vars; ++v) cube.care[v / 64] |= uint64_t{1} << (v % 64);
    exact.push_back(cube);
  }
  return cube_lemmas(table, exact, rule_.ctx().bool_val(true));
}

z3::expr_vector SymbolicCycle::cube_lemmas(const CycleTable& table,
                                           const std::vector<PatternCube>& cubes,
                                           const z3::expr& guard) const {
  z3::context& c = rule_.ctx();
  z3::expr_vector out(c);
  const int n = rule_.slots();
  const size_t nl = table.labels.size();
  for (unsigned s = 1; s < ok_.size(); ++s) {
    const std::vector<int> slot = slots_of(s, n);
    const size_t k = slot.size();
    // The pattern variables on the slots of S, in pattern_bits order.
    std::vector<z3::expr> var;
    for (size_t x = 0; x < k; ++x) {
      var.push_back(rule_.in_left(slot[x]));
      var.push_back(rule_.in_right(slot[x]));
    }
    for (bool right : {false, true})
      for (size_t l = 0; l < nl; ++l)
        for (size_t x = 0; x < k; ++x)
          for (size_t y = 0; y < k; ++y)
            var.push_back(rule_.arc(right, table.labels[l], slot[x], slot[y]));
    for (const PatternCube& cube : cubes) {
      if (cube.nodes != k) continue;
      z3::expr_vector clause(c);
      for (size_t v = 0; v < var.size(); ++v) {
        if (!((cube.care[v / 64] >> (v % 64)) & 1u)) continue;
        clause.push_back((cube.value[v / 64] >> (v % 64)) & 1u ? !var[v] : var[v]);
      }
      clause.push_back(cube.holds ? ok_[s] : !ok_[s]);
      if (!guard.is_true()) clause.push_back(!guard);
      out.push_back(z3::mk_or(clause));
    }
  }
  return out;
}

}  // namespace gmr::smt
