// Cycle condition C_r(i,j): ij-completion (Assumption 5), optimal paths (Def. 38), coherence
// (Def. 39) and the condition itself (Def. 40). Readings: rule_check.hpp.
#include <functional>
#include <set>

#include "checker/rule_check.hpp"
#include "model/core/error.hpp"
#include "model/rewrite/match.hpp"

namespace gmr::checker {
using namespace gmr::graph;
using namespace gmr::rewrite;

namespace {

bool has_arc(const DGraph& g, Node s, Node t, int l) {
  for (ArcId a : g.out_arcs(s))
    if (g.arc(a).tgt == t && g.arc(a).label == l) return true;
  return false;
}

bool has_out(const DGraph& g, Node s, int l) { return !g.successors(s, l).empty(); }
bool has_in(const DGraph& g, Node t, int l) { return !g.predecessors(t, l).empty(); }

std::string lbl(int l) { return std::to_string(l); }

bool combinatorial_on(const DGraph& g, int i, int j) {
  for (Node v : g.nodes())
    for (int l : {i, j})
      if (g.successors(v, l).size() > 1 || g.predecessors(v, l).size() > 1) return false;
  return true;
}

std::vector<std::string> path_names(const DGraph& g, const OptimalPath& p) {
  std::vector<std::string> s{g.name(p.source)};
  for (ArcId a : p.arcs) s.push_back(g.name(g.arc(a).tgt));
  return s;
}

}  // namespace

Rule ij_complete(const Rule& r, int i, int j, std::vector<Diagnostic>* notes) {
  DGraph L = r.left(), R = r.right();
  std::set<std::string> seen;
  auto note = [&](const std::string& code, const std::string& msg, std::vector<std::string> path,
                  std::optional<Side> side) {
    if (!notes || !seen.insert(code + msg).second) return;
    notes->push_back(Diagnostic{.code = code,
                                .severity = Severity::Note,
                                .condition = symbol(Constraint::Cycle),
                                .i = i,
                                .j = j,
                                .side = side,
                                .path = std::move(path),
                                .message = msg});
  };
  auto name_of_r = [&](Node l) { return R.find(L.name(l)); };
  bool changed = true;
  while (changed) {
    changed = false;
    for (auto [a, b] : {std::pair{i, j}, std::pair{j, i}}) {
      for (ArcId e1(0); e1.index() < L.num_arc_slots() && !changed; ++e1) {
        if (!L.arc_alive(e1) || L.arc(e1).label != a) continue;
        const Node u0 = L.arc(e1).src, u1 = L.arc(e1).tgt;
        for (Node u2 : L.successors(u1, b)) {
          for (Node u3 : L.successors(u2, a)) {
            if (has_arc(L, u3, u0, b)) continue;
            std::vector<std::string> path{L.name(u0), L.name(u1), L.name(u2), L.name(u3)};
            const std::string w = lbl(a) + lbl(b) + lbl(a);
            if (has_out(L, u3, b) || has_in(L, u0, b)) {
              note("C-completion-conflict",
                   "the " + w + "-path cannot be closed by a " + lbl(b) + "-arc " + L.name(u3) +
                       " -> " + L.name(u0) + " (another " + lbl(b) +
                       "-arc is already there): L matches no graph satisfying C_G(" + lbl(i) + "," +
                       lbl(j) + ")",
                   path, Side::L);
              continue;
            }
            auto r3 = name_of_r(u3), r0 = name_of_r(u0);
            if (!r3 || !r0) continue;  // a deleted end: I_r fails there (dangling arc)
            L.add_arc(u3, u0, b);
            R.add_arc(*r3, *r0, b);
            note("C-completed",
                 "ij-completion: the " + w + "-path is closed by the preserved " + lbl(b) +
                     "-arc " + L.name(u3) + " -> " + L.name(u0) +
                     " added to L and R (Assumption 5)",
                 path, Side::L);
            changed = true;
            break;
          }
          if (changed) break;
        }
      }
      if (changed) break;
    }
  }
  for (auto [a, b] : {std::pair{i, j}, std::pair{j, i}})
    for (ArcId e1 : R.arc_slots()) {
      if (!R.arc_alive(e1) || R.arc(e1).label != a) continue;
      const Node u0 = R.arc(e1).src, u1 = R.arc(e1).tgt;
      for (Node u2 : R.successors(u1, b))
        for (Node u3 : R.successors(u2, a))
          if (!has_arc(R, u3, u0, b))
            note(
                "C-open-R",
                "the " + lbl(a) + lbl(b) + lbl(a) + "-path of R is not closed in R (not completed)",
                {R.name(u0), R.name(u1), R.name(u2), R.name(u3)}, Side::R);
    }
  return Rule(std::move(L), std::move(R), r.dimension(), r.kind(), r.name());
}

Rule complete_for_model(const Rule& r0, std::vector<Diagnostic>* notes) {
  Rule r = r0;
  std::set<std::string> seen;
  auto note = [&](Diagnostic d) {
    if (!notes || !seen.insert(d.code + d.message).second) return;
    notes->push_back(std::move(d));
  };
  for (;;) {
    DGraph L = r.left(), R = r.right();
    bool changed = false;
    for (int i : r.labels()) {
      if (r.kind() == MapKind::OMap && i == 1) continue;
      for (ArcId a : L.arc_slots()) {
        if (!L.arc_alive(a) || L.arc(a).label != i) continue;
        const Node u = L.arc(a).src, v = L.arc(a).tgt;
        if (has_arc(L, v, u, i)) continue;
        auto ru = R.find(L.name(u)), rv = R.find(L.name(v));
        if (!ru || !rv || has_out(L, v, i) || has_in(L, u, i))
          continue;  // I_r / vacuity handle these
        L.add_arc(v, u, i);
        R.add_arc(*rv, *ru, i);
        note({.code = "C-O-completed",
              .severity = Severity::Note,
              .condition = symbol(Constraint::Cycle),
              .i = i,
              .side = Side::L,
              .nodes = {L.name(u), L.name(v)},
              .message = "model completion: the reverse " + lbl(i) + "-arc " + L.name(v) + " -> " +
                         L.name(u) + " of " + L.name(u) + " -> " + L.name(v) +
                         " was added to L and R (preserved) before checking C_r"});
        changed = true;
      }
    }
    Rule next(std::move(L), std::move(R), r.dimension(), r.kind(), r.name());
    for (int i : r.labels())
      for (int j : r.labels())
        if (j >= i + 2) {
          const size_t before = next.left().num_arcs();
          std::vector<Diagnostic> ns;
          next = ij_complete(next, i, j, &ns);
          for (auto& d : ns)
            if (d.code != "C-open-R") note(std::move(d));
          changed = changed || next.left().num_arcs() != before;
        }
    r = std::move(next);
    if (!changed) return r;
  }
}

bool on_alternating_cycle(const DGraph& g, ArcId a, int i, int j) {
  const Arc& e = g.arc(a);
  std::function<bool(Node, int, int)> walk = [&](Node at, int label, int steps) -> bool {
    if (steps == 4) return at == e.src;
    for (Node w : g.successors(at, label))
      if (walk(w, label == i ? j : i, steps + 1)) return true;
    return false;
  };
  return walk(e.tgt, e.label == i ? j : i, 1);
}

std::vector<OptimalPath> optimal_paths(const Rule& r, Side side, int i, int j) {
  const DGraph& g = r.side(side);
  if (!combinatorial_on(g, i, j))
    throw Error(ErrorCode::Usage,
                "optimal paths need a side with at most one i- and j-arc per node",
                side == Side::R ? "right" : "left");
  const ElemStatus changed = side == Side::R ? ElemStatus::Added : ElemStatus::Deleted;
  HandleVector<ArcId, bool> in(g.num_arc_slots(), false);
  for (ArcId a : g.arc_slots())
    in[a] = g.arc_alive(a) && (g.arc(a).label == i || g.arc(a).label == j) &&
            r.arc_status(side, a) == changed;
  auto other = [&](int l) { return l == i ? j : i; };
  auto succ = [&](ArcId a) -> ArcId {
    for (ArcId b : g.out_arcs(g.arc(a).tgt))
      if (in[b] && g.arc(b).label == other(g.arc(a).label)) return b;
    return kNoArc;
  };
  auto pred = [&](ArcId a) -> ArcId {
    for (ArcId b : g.in_arcs(g.arc(a).src))
      if (in[b] && g.arc(b).label == other(g.arc(a).label)) return b;
    return kNoArc;
  };
  std::vector<OptimalPath> cand;
  HandleVector<ArcId, bool> done(g.num_arc_slots(), false);
  auto make = [&](const std::vector<ArcId>& arcs) {
    OptimalPath p;
    p.arcs = arcs;
    p.source = g.arc(arcs.front()).src;
    p.target = g.arc(arcs.back()).tgt;
    for (ArcId a : arcs) p.word.push_back(g.arc(a).label);
    cand.push_back(std::move(p));
  };
  for (ArcId a : g.arc_slots()) {  // open chains
    if (!in[a] || pred(a) != kNoArc) continue;
    std::vector<ArcId> chain;
    for (ArcId b = a; b != kNoArc; b = succ(b)) {
      chain.push_back(b);
      done[b] = true;
    }
    make(chain);
  }
  for (ArcId a : g.arc_slots()) {  // closed chains: every rotation (Def. 38.4)
    if (!in[a] || done[a]) continue;
    std::vector<ArcId> cyc;
    for (ArcId b = a; !done[b]; b = succ(b)) {
      cyc.push_back(b);
      done[b] = true;
    }
    for (size_t k = 0; k < cyc.size(); ++k) {
      std::vector<ArcId> rot(cyc.begin() + static_cast<long>(k), cyc.end());
      rot.insert(rot.end(), cyc.begin(), cyc.begin() + static_cast<long>(k));
      make(rot);
    }
  }
  std::vector<OptimalPath> out;
  for (auto& p : cand)
    if (!(p.arcs.size() <= 4 && on_alternating_cycle(g, p.arcs.front(), i, j)))
      out.push_back(std::move(p));
  return out;
}

namespace {

// Def. 40.1 (with Def. 39): every (i,j)-optimal path of one side has exactly one coherent optimal
// path (same source, target and label word) on the other side.
bool check_coherent_partners(const Rule& r, const std::vector<OptimalPath>& PL,
                             const std::vector<OptimalPath>& PR, int i, int j,
                             std::vector<Diagnostic>& out) {
  bool ok = true;
  const DGraph &L = r.left(), &R = r.right();
  for (Side side : {Side::L, Side::R}) {
    const bool right = side == Side::R;
    const auto& mine = right ? PR : PL;
    const auto& theirs = right ? PL : PR;
    const DGraph& g = right ? R : L;
    const DGraph& h = right ? L : R;
    for (const auto& p : mine) {
      size_t partners = 0;
      for (const auto& q : theirs)
        if (h.name(q.source) == g.name(p.source) && h.name(q.target) == g.name(p.target) &&
            q.word == p.word)
          ++partners;
      if (partners == 1) continue;
      ok = false;
      Diagnostic d{.code = partners == 0 ? "C-incoherent" : "C-ambiguous",
                   .condition = symbol(Constraint::Cycle),
                   .i = i,
                   .j = j,
                   .side = side,
                   .path = path_names(g, p)};
      d.message = "the (" + lbl(i) + "," + lbl(j) + ")-optimal path " + g.name(p.source) + " ~" +
                  word_text(p.word) + "~> " + g.name(p.target) + " of " + to_string(side) +
                  " has " + std::to_string(partners) + " coherent optimal paths in " +
                  to_string(other(side)) + "; exactly one is required (Defs. 39, 40.1)";
      d.nodes = {g.name(p.source), g.name(p.target)};
      for (ArcId a : p.arcs) d.arcs.push_back(r.arc_str(side, a));
      out.push_back(std::move(d));
    }
  }
  return ok;
}

// Def. 40.2 and 40.3: a preserved node losing an i-arc (j-arc) and an added node have their
// i-arc (j-arc) of R on an ijij-cycle or on an (i,j)-optimal path of R.
bool check_rewired_nodes_covered(const Rule& r, const std::vector<OptimalPath>& PR, int i, int j,
                                 std::vector<Diagnostic>& out) {
  bool ok = true;
  const DGraph &L = r.left(), &R = r.right();
  std::set<ArcId> on_opt;
  for (const auto& p : PR) on_opt.insert(p.arcs.begin(), p.arcs.end());
  auto covered = [&](Node w, int d) {
    for (ArcId a : R.out_arcs(w))
      if (R.arc(a).label == d && (on_opt.count(a) || on_alternating_cycle(R, a, i, j))) return true;
    return false;
  };
  for (Node v : r.preserved_nodes()) {
    const Node w = *r.right_of(v);
    for (int d : {i, j}) {
      bool rewired = false;
      for (ArcId a : L.out_arcs(v))
        if (L.arc(a).label == d && r.left_arc_status(a) == ElemStatus::Deleted) rewired = true;
      if (!rewired || covered(w, d)) continue;
      ok = false;
      Diagnostic dg{.code = "C-preserved-node",
                    .condition = symbol(Constraint::Cycle),
                    .i = i,
                    .j = j,
                    .side = Side::R,
                    .nodes = {L.name(v)}};
      dg.message = "preserved node " + L.name(v) + " loses its " + lbl(d) + "-arc but its " +
                   lbl(d) + "-arc in R is neither on an " + lbl(i) + lbl(j) + lbl(i) + lbl(j) +
                   "-cycle nor on an (" + lbl(i) + "," + lbl(j) + ")-optimal path (Def. 40.2)";
      for (ArcId a : R.out_arcs(w))
        if (R.arc(a).label == d) dg.arcs.push_back(r.arc_str(Side::R, a));
      out.push_back(std::move(dg));
    }
  }
  for (Node w : r.added_nodes()) {
    for (int d : {i, j}) {
      if (covered(w, d)) continue;
      ok = false;
      Diagnostic dg{.code = "C-added-node",
                    .condition = symbol(Constraint::Cycle),
                    .i = i,
                    .j = j,
                    .side = Side::R,
                    .nodes = {R.name(w)}};
      dg.message = "added node " + R.name(w) + " is not the source of a " + lbl(d) + "-arc on an " +
                   lbl(i) + lbl(j) + lbl(i) + lbl(j) + "-cycle or on an (" + lbl(i) + "," + lbl(j) +
                   ")-optimal path of R (Def. 40.3)";
      for (ArcId a : R.out_arcs(w))
        if (R.arc(a).label == d) dg.arcs.push_back(r.arc_str(Side::R, a));
      out.push_back(std::move(dg));
    }
  }
  return ok;
}

}  // namespace

bool check_cycle(const Rule& r0, int i, int j, std::vector<Diagnostic>& out) {
  std::vector<Diagnostic> notes;
  const Rule r = ij_complete(r0, i, j, &notes);
  for (auto& n : notes) out.push_back(std::move(n));
  return check_cycle_as_written(r, i, j, out);
}

bool check_cycle_as_written(const Rule& r, int i, int j, std::vector<Diagnostic>& out) {
  if (!combinatorial_on(r.left(), i, j) || !combinatorial_on(r.right(), i, j)) {
    out.push_back({.code = "C-skipped",
                   .severity = Severity::Note,
                   .condition = symbol(Constraint::Cycle),
                   .i = i,
                   .j = j,
                   .message = "not evaluated: a node has two " + lbl(i) + "- or " + lbl(j) +
                              "-arcs on one side (the rule fails Def. 35 or I_r)"});
    return true;
  }
  const auto PL = optimal_paths(r, Side::L, i, j), PR = optimal_paths(r, Side::R, i, j);
  const bool coherent = check_coherent_partners(r, PL, PR, i, j, out);
  const bool covered = check_rewired_nodes_covered(r, PR, i, j, out);
  return coherent && covered;
}

}  // namespace gmr::checker
