#include "checker/smt/symbolic_rule.hpp"

#include <algorithm>
#include <stdexcept>

#include "model/core/error.hpp"

namespace gmr::smt {
using graph::DGraph;
using graph::Node;

SymbolicRule::SymbolicRule(z3::context& ctx, MapSpec spec, int max_nodes, std::vector<int> labels)
    : ctx_(ctx), spec_(spec), slots_(max_nodes), labels_(std::move(labels)) {
  const std::string node = "abcdefgh";
  for (int x = 0; x < slots_; ++x) {
    in_left_.push_back(ctx_.bool_const(("inL_" + node.substr(x, 1)).c_str()));
    in_right_.push_back(ctx_.bool_const(("inR_" + node.substr(x, 1)).c_str()));
  }
  for (int side = 0; side < 2; ++side) {
    arcs_.emplace_back();
    for (int i : labels_) {
      arcs_[side].emplace_back();
      for (int x = 0; x < slots_; ++x)
        for (int y = 0; y < slots_; ++y) {
          const std::string name = std::string(side ? "R_" : "L_") + node.substr(x, 1) +
                                   std::to_string(i) + node.substr(y, 1);
          arcs_[side].back().push_back(ctx_.bool_const(name.c_str()));
        }
    }
  }
}

int SymbolicRule::label_index(int i) const {
  const auto it = std::find(labels_.begin(), labels_.end(), i);
  return it == labels_.end() ? -1 : static_cast<int>(it - labels_.begin());
}

z3::expr SymbolicRule::arc(bool right, int i, int x, int y) const {
  const int k = label_index(i);
  if (k < 0) return ctx_.bool_val(false);
  return arcs_[right][k][x * slots_ + y];
}

z3::expr SymbolicRule::has_out(bool right, int i, int x) const {
  z3::expr_vector any(ctx_);
  for (int y = 0; y < slots_; ++y) any.push_back(arc(right, i, x, y));
  return z3::mk_or(any);
}

z3::expr SymbolicRule::has_in(bool right, int i, int x) const {
  z3::expr_vector any(ctx_);
  for (int y = 0; y < slots_; ++y) any.push_back(arc(right, i, y, x));
  return z3::mk_or(any);
}

z3::expr_vector SymbolicRule::family() const {
  z3::expr_vector out(ctx_);
  out.push_back(exists(0));
  for (int x = 0; x + 1 < slots_; ++x) {
    // Existing slots form a prefix; statuses nondecreasing: preserved < deleted < added.
    out.push_back(z3::implies(exists(x + 1), exists(x)));
    out.push_back(z3::implies(exists(x + 1), !(deleted(x) && preserved(x + 1))));
    out.push_back(z3::implies(exists(x + 1), !(added(x) && (preserved(x + 1) || deleted(x + 1)))));
  }
  for (bool right : {false, true}) {
    const auto& side = right ? in_right_ : in_left_;
    for (int i : labels_)
      for (int x = 0; x < slots_; ++x)
        for (int y = 0; y < slots_; ++y) {
          out.push_back(z3::implies(arc(right, i, x, y), side[x] && side[y]));
          // A partial injection: one outgoing i-arc per source, one incoming per target.
          for (int z = y + 1; z < slots_; ++z) {
            out.push_back(!(arc(right, i, x, y) && arc(right, i, x, z)));
            out.push_back(!(arc(right, i, y, x) && arc(right, i, z, x)));
          }
        }
  }
  return out;
}

z3::expr SymbolicRule::nodes_exactly(int m) const {
  z3::expr e = m >= 1 ? exists(m - 1) : ctx_.bool_val(true);
  if (m < slots_) e = e && !exists(m);
  return e;
}

z3::expr SymbolicRule::condition(const ThesisParts& parts) const {
  z3::expr_vector all(ctx_);
  for (int i : spec_.labels()) {
    for (int x = 0; x < slots_; ++x) {
      // w-I_r(i), Def. 33.1 (preserved nodes) and 33.2 (added nodes).
      all.push_back(z3::implies(preserved(x), has_out(false, i, x) == has_out(true, i, x) &&
                                                  has_in(false, i, x) == has_in(true, i, x)));
      all.push_back(z3::implies(added(x), has_out(true, i, x) && has_in(true, i, x)));
      // The dangling part of I_r(i), Def. 34 / Fact 1.
      if (parts.dangling)
        all.push_back(z3::implies(deleted(x), has_out(false, i, x) && has_in(false, i, x)));
    }
    // O_r(i), Def. 37.
    if (parts.orientation && spec_.is_involutive_dim(i))
      for (int x = 0; x < slots_; ++x)
        for (int y = 0; y < slots_; ++y) {
          if (x == y) continue;  // a loop is its own reverse
          all.push_back(z3::implies(deleted_arc(i, x, y), deleted_arc(i, y, x)));
          all.push_back(z3::implies(added_arc(i, x, y), added_arc(i, y, x)));
        }
  }
  return z3::mk_and(all);
}

rewrite::Rule SymbolicRule::extract(const z3::model& m, const std::string& name) const {
  auto val = [&](const z3::expr& e) { return m.eval(e, true).is_true(); };
  DGraph L, R;
  std::vector<graph::Node> left(slots_, graph::kNoNode), right(slots_, graph::kNoNode);
  const std::string node = "abcdefgh";
  for (int x = 0; x < slots_; ++x) {
    if (val(in_left_[x])) left[x] = L.add_node(node.substr(x, 1));
    if (val(in_right_[x])) right[x] = R.add_node(node.substr(x, 1));
  }
  for (int i : labels_)
    for (int x = 0; x < slots_; ++x)
      for (int y = 0; y < slots_; ++y) {
        if (left[x] != graph::kNoNode && left[y] != graph::kNoNode && val(arc(false, i, x, y)))
          L.add_arc(left[x], left[y], i);
        if (right[x] != graph::kNoNode && right[y] != graph::kNoNode && val(arc(true, i, x, y)))
          R.add_arc(right[x], right[y], i);
      }
  return rewrite::Rule(std::move(L), std::move(R), spec_.n, spec_.kind, name);
}

z3::expr SymbolicRule::equals(const z3::model& m) const {
  z3::expr_vector all(ctx_);
  auto fix = [&](const z3::expr& e) { all.push_back(e == m.eval(e, true)); };
  for (int x = 0; x < slots_; ++x) {
    fix(in_left_[x]);
    fix(in_right_[x]);
  }
  for (const auto& side : arcs_)
    for (const auto& label : side)
      for (const auto& e : label) fix(e);
  return z3::mk_and(all);
}

z3::expr SymbolicRule::equals_on(const z3::model& m, const std::vector<int>& labels) const {
  z3::expr_vector all(ctx_);
  auto fix = [&](const z3::expr& e) { all.push_back(e == m.eval(e, true)); };
  for (int x = 0; x < slots_; ++x) {
    fix(in_left_[x]);
    fix(in_right_[x]);
  }
  for (int i : labels) {
    const int k = label_index(i);
    if (k < 0) continue;  // no arcs on that label
    for (const auto& side : arcs_)
      for (const auto& e : side[k]) fix(e);
  }
  return z3::mk_and(all);
}

z3::expr SymbolicRule::describes(const rewrite::Rule& r) const {
  z3::expr_vector all(ctx_);
  const std::string node = "abcdefgh";
  std::vector<HandleVector<graph::Node, int>> slot_of(2);  // per side: node -> slot
  for (graph::Side side : graph::kSides) {
    const unsigned right = graph::index_of(side);
    const DGraph& g = r.side(side);
    std::vector<bool> present(slots_, false);
    for (Node v : g.nodes()) {
      const auto x = node.find(g.name(v));
      if (g.name(v).size() != 1 || x == std::string::npos || static_cast<int>(x) >= slots_)
        throw Error(ErrorCode::Usage, "node " + g.name(v) + " is not a slot of the symbolic rule",
                    "rule " + r.name());
      slot_of[right].push_back(static_cast<int>(x));
      present[x] = true;
    }
    for (int x = 0; x < slots_; ++x)
      all.push_back(right ? in_right_[x] == ctx_.bool_val(present[x])
                          : in_left_[x] == ctx_.bool_val(present[x]));
    std::vector<bool> arcs(labels_.size() * slots_ * slots_, false);
    for (graph::ArcId a : g.arc_slots()) {
      if (!g.arc_alive(a)) continue;
      const int k = label_index(g.arc(a).label);
      if (k < 0)
        throw Error(ErrorCode::Usage, "an arc on a label outside the family's", "rule " + r.name());
      arcs[(k * slots_ + slot_of[right][g.arc(a).src]) * slots_ + slot_of[right][g.arc(a).tgt]] =
          true;
    }
    for (size_t k = 0; k < labels_.size(); ++k)
      for (int e = 0; e < slots_ * slots_; ++e)
        all.push_back(arcs_[right][k][e] == ctx_.bool_val(arcs[k * slots_ * slots_ + e]));
  }
  return z3::mk_and(all);
}

}  // namespace gmr::smt
