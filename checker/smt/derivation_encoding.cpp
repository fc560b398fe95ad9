#include "checker/smt/derivation_encoding.hpp"

#include <set>
#include <string>
#include <tuple>

namespace gmr::smt {
using graph::ArcId;
using graph::DGraph;
using graph::ElemStatus;
using graph::Node;

DerivationEncoding::DerivationEncoding(const MapEncoding& map, const Rule& rule, bool fixed_match)
    : map_(map), rule_(rule), added_index_(rule.right().num_nodes(), -1) {
  z3::context& c = map_.ctx();
  for (Node v : rule_.left().nodes())
    m_.push_back(fixed_match ? map_.dart(v.index())
                             : c.constant(("m_" + rule_.left().name(v)).c_str(), map_.sort()));
  for (Node r : rule_.added_nodes()) {
    added_index_[r] = static_cast<int>(added_.size());
    added_.push_back(r);
  }
  for (int i = 0; i <= map_.spec().n; ++i)
    h_.push_back(c.function(("h" + std::to_string(i)).c_str(), map_.sort(), map_.sort()));
}

z3::expr DerivationEncoding::h_node(Node r) const {
  if (auto l = rule_.left_of(r)) return m_[*l];
  return map_.dart(map_.capacity() + static_cast<unsigned>(added_index_[r]));
}

z3::expr_vector DerivationEncoding::match_constraints() const {
  z3::context& c = map_.ctx();
  z3::expr_vector out(c);
  const DGraph& L = rule_.left();
  if (!m_.empty()) {
    z3::expr_vector all(c);
    for (const auto& e : m_) {
      out.push_back(map_.active_term(e));
      all.push_back(e);
    }
    if (m_.size() > 1) out.push_back(z3::distinct(all));
  }
  std::set<std::tuple<Node, Node, int>> seen;
  for (ArcId a : L.arc_slots()) {
    if (!L.arc_alive(a)) continue;
    const auto& arc = L.arc(a);
    // Parallel arcs need distinct images, and a map has one i-arc per dart and label.
    if (!seen.insert({arc.src, arc.tgt, arc.label}).second) out.push_back(c.bool_val(false));
    out.push_back(map_.alpha(arc.label, m_[arc.src]) == m_[arc.tgt]);
  }
  return out;
}

z3::expr DerivationEncoding::dangling_condition() const {
  z3::context& c = map_.ctx();
  const DGraph& L = rule_.left();
  z3::expr_vector all(c);
  for (Node v : rule_.deleted_nodes()) {
    for (int i : map_.spec().labels()) {
      z3::expr_vector out_covered(c), in_covered(c);
      for (ArcId a : L.arc_slots()) {
        if (!L.arc_alive(a) || L.arc(a).label != i) continue;
        const auto& arc = L.arc(a);
        if (arc.src == v) out_covered.push_back(map_.alpha(i, m_[v]) == m_[arc.tgt]);
        if (arc.tgt == v) in_covered.push_back(map_.alpha_inverse(i, m_[v]) == m_[arc.src]);
      }
      all.push_back(z3::mk_or(out_covered));
      all.push_back(z3::mk_or(in_covered));
    }
  }
  return z3::mk_and(all);
}

z3::expr DerivationEncoding::alive(unsigned x) const {
  if (x >= map_.capacity()) return map_.ctx().bool_val(true);
  return alive_term(map_.dart(x));
}

z3::expr DerivationEncoding::alive_term(const z3::expr& X) const {
  z3::expr_vector deleted(map_.ctx());
  for (Node v : rule_.deleted_nodes()) deleted.push_back(m_[v] == X);
  return map_.active_term(X) && !z3::mk_or(deleted);
}

std::vector<DerivationEncoding::Candidate> DerivationEncoding::out_arcs(unsigned x, int i) const {
  return out_arcs(map_.dart(x), x < map_.capacity(), i);
}

std::vector<DerivationEncoding::Candidate> DerivationEncoding::out_arcs(const z3::expr& X,
                                                                        bool g_dart, int i) const {
  z3::context& c = map_.ctx();
  std::vector<Candidate> out;
  if (g_dart) {
    // G's i-arc leaving x survives unless a deleted L-arc is matched onto it.
    z3::expr_vector removed(c);
    const DGraph& L = rule_.left();
    for (ArcId a : L.arc_slots())
      if (L.arc_alive(a) && L.arc(a).label == i && rule_.left_arc_status(a) == ElemStatus::Deleted)
        removed.push_back(m_[L.arc(a).src] == X);
    out.push_back({alive_term(X) && !z3::mk_or(removed), map_.alpha(i, X)});
  }
  const DGraph& R = rule_.right();
  for (ArcId a : R.arc_slots())
    if (R.arc_alive(a) && R.arc(a).label == i && rule_.right_arc_status(a) == ElemStatus::Added)
      out.push_back({h_node(R.arc(a).src) == X, h_node(R.arc(a).tgt)});
  return out;
}

std::vector<DerivationEncoding::Candidate> DerivationEncoding::in_arcs(unsigned x, int i) const {
  return in_arcs(map_.dart(x), x < map_.capacity(), i);
}

std::vector<DerivationEncoding::Candidate> DerivationEncoding::in_arcs(const z3::expr& X,
                                                                       bool g_dart, int i) const {
  z3::context& c = map_.ctx();
  std::vector<Candidate> in;
  if (g_dart) {
    // G's i-arc entering x (from alpha_i^-1(x)); a deleted L-arc u -i-> w is matched onto it iff
    // m(w) = x.
    z3::expr_vector removed(c);
    const DGraph& L = rule_.left();
    for (ArcId a : L.arc_slots())
      if (L.arc_alive(a) && L.arc(a).label == i && rule_.left_arc_status(a) == ElemStatus::Deleted)
        removed.push_back(m_[L.arc(a).tgt] == X);
    in.push_back({alive_term(X) && !z3::mk_or(removed), map_.alpha_inverse(i, X)});
  }
  const DGraph& R = rule_.right();
  for (ArcId a : R.arc_slots())
    if (R.arc_alive(a) && R.arc(a).label == i && rule_.right_arc_status(a) == ElemStatus::Added)
      in.push_back({h_node(R.arc(a).tgt) == X, h_node(R.arc(a).src)});
  return in;
}

z3::expr DerivationEncoding::exactly_one(const std::vector<Candidate>& cs) const {
  z3::context& c = map_.ctx();
  z3::expr_vector one(c);
  for (size_t k = 0; k < cs.size(); ++k) {
    z3::expr_vector others(c);
    for (size_t l = 0; l < cs.size(); ++l)
      if (l != k) others.push_back(!cs[l].present);
    one.push_back(cs[k].present && z3::mk_and(others));
  }
  return z3::mk_or(one);
}

z3::expr_vector DerivationEncoding::h_definitions() const {
  z3::expr_vector out(map_.ctx());
  for (int i : map_.spec().labels()) {
    for (unsigned x = 0; x < num_h_nodes(); ++x) {
      const auto cs = out_arcs(x, i);
      if (cs.empty()) continue;  // an added node without outgoing i-arc: I_H(i) fails there
      z3::expr target = cs.back().end;
      for (size_t k = cs.size() - 1; k-- > 0;) target = z3::ite(cs[k].present, cs[k].end, target);
      out.push_back(z3::implies(alive(x), h(i, map_.dart(x)) == target));
    }
  }
  return out;
}

z3::expr DerivationEncoding::violates(Constraint kind, unsigned x, int i, int j) const {
  const z3::expr X = map_.dart(x);
  switch (kind) {
    case Constraint::IncidentArcs:
      return alive(x) && !(exactly_one(out_arcs(x, i)) && exactly_one(in_arcs(x, i)));
    case Constraint::NonOrientation:
      return alive(x) && h(i, h(i, X)) != X;
    case Constraint::Cycle:
      return alive(x) && h(j, h(i, h(j, h(i, X)))) != X;
  }
  return map_.ctx().bool_val(false);
}

z3::expr DerivationEncoding::breaks_model_local() const {
  // The nodes of H a rewrite touches: images of the preserved nodes and the added nodes.
  std::vector<std::pair<z3::expr, bool>> image;
  for (Node v : rule_.preserved_nodes()) image.emplace_back(m_[v], true);
  for (unsigned a = 0; a < added_.size(); ++a)
    image.emplace_back(map_.dart(map_.capacity() + a), false);
  z3::expr_vector any(map_.ctx());
  const MapSpec& s = map_.spec();
  for (const auto& [X, g_dart] : image) {
    for (int i : s.labels()) {
      any.push_back(!(exactly_one(out_arcs(X, g_dart, i)) && exactly_one(in_arcs(X, g_dart, i))));
      if (s.is_involutive_dim(i)) any.push_back(h(i, h(i, X)) != X);
    }
    for (auto [i, j] : s.cycle_pairs()) {
      any.push_back(h(j, h(i, h(j, h(i, X)))) != X);
      any.push_back(h(i, h(j, h(i, h(j, X)))) != X);
    }
  }
  return z3::mk_or(any);
}

z3::expr DerivationEncoding::breaks_model() const {
  z3::expr_vector any(map_.ctx());
  const MapSpec& s = map_.spec();
  for (unsigned x = 0; x < num_h_nodes(); ++x) {
    for (int i : s.labels()) {
      any.push_back(violates(Constraint::IncidentArcs, x, i));
      if (s.is_involutive_dim(i)) any.push_back(violates(Constraint::NonOrientation, x, i));
    }
    for (auto [i, j] : s.cycle_pairs()) any.push_back(violates(Constraint::Cycle, x, i, j));
  }
  return z3::mk_or(any);
}

}  // namespace gmr::smt
