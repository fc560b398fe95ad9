// Incident arcs: Def. 35 (combinatorial rule), Def. 33 (w-I_r(i)), Def. 34 (I_r(i)), Fact 1.
#include <algorithm>
#include <map>

#include "checker/rule_check.hpp"

namespace gmr::checker {
using namespace gmr::graph;
using namespace gmr::rewrite;

namespace {

std::vector<ArcId> arcs_with(const DGraph& g, const std::vector<ArcId>& ids, int i) {
  std::vector<ArcId> out;
  for (ArcId a : ids)
    if (g.arc(a).label == i) out.push_back(a);
  return out;
}

std::vector<std::string> arc_strs(const Rule& r, Side side, const std::vector<ArcId>& ids) {
  std::vector<std::string> s;
  for (ArcId a : ids) s.push_back(r.arc_str(side, a));
  return s;
}

std::string count_str(size_t k, const char* dir, int i) {
  return std::to_string(k) + " " + dir + " " + std::to_string(i) + "-arc" + (k == 1 ? "" : "s");
}

bool weak(const Rule& r, int i, std::vector<Diagnostic>& out, const char* cond) {
  bool ok = true;
  const DGraph &L = r.left(), &R = r.right();
  for (Node v : r.preserved_nodes()) {
    const Node w = *r.right_of(v);
    for (int dir = 0; dir < 2; ++dir) {
      const auto l = arcs_with(L, dir ? L.in_arcs(v) : L.out_arcs(v), i);
      const auto rr = arcs_with(R, dir ? R.in_arcs(w) : R.out_arcs(w), i);
      if (l.size() == rr.size()) continue;
      ok = false;
      Diagnostic d{.code = "I-preserved-node", .condition = cond, .i = i};
      const char* what = dir ? "incoming" : "outgoing";
      d.message = "preserved node " + L.name(v) + " has " + count_str(l.size(), what, i) +
                  " in L but " + count_str(rr.size(), what, i) + " in R (Def. 33.1)";
      d.nodes = {L.name(v)};
      d.arcs = arc_strs(r, Side::L, l);
      for (auto& s : arc_strs(r, Side::R, rr)) d.arcs.push_back(s);
      out.push_back(std::move(d));
    }
  }
  for (Node w : r.added_nodes()) {
    const auto o = arcs_with(R, R.out_arcs(w), i), in = arcs_with(R, R.in_arcs(w), i);
    if (o.size() == 1 && in.size() == 1) continue;
    ok = false;
    Diagnostic d{.code = "I-added-node", .condition = cond, .i = i};
    d.message = "added node " + R.name(w) + " is the source of " +
                count_str(o.size(), "outgoing", i) + " and the target of " +
                count_str(in.size(), "incoming", i) +
                " in R; exactly one each is required (Def. 33.2)";
    d.nodes = {R.name(w)};
    d.arcs = arc_strs(r, Side::R, o);
    for (auto& s : arc_strs(r, Side::R, in))
      if (std::find(d.arcs.begin(), d.arcs.end(), s) == d.arcs.end()) d.arcs.push_back(s);
    out.push_back(std::move(d));
  }
  return ok;
}

}  // namespace

bool check_combinatorial(const Rule& r, std::vector<Diagnostic>& out) {
  bool ok = true;
  const DGraph& L = r.left();
  for (Node v : L.nodes()) {
    for (int dir = 0; dir < 2; ++dir) {
      std::map<int, std::vector<ArcId>> by;
      for (ArcId a : dir ? L.in_arcs(v) : L.out_arcs(v)) by[L.arc(a).label].push_back(a);
      for (auto& [i, arcs] : by) {
        if (arcs.size() <= 1) continue;
        ok = false;
        Diagnostic d{
            .code = "comb-multiple-arcs", .condition = "combinatorial", .i = i, .side = Side::L};
        d.message = "node " + L.name(v) + " is the " + (dir ? "target" : "source") + " of " +
                    std::to_string(arcs.size()) + " " + std::to_string(i) +
                    "-arcs in L; no injective match into a combinatorial graph exists (Def. 35)";
        d.nodes = {L.name(v)};
        d.arcs = arc_strs(r, Side::L, arcs);
        out.push_back(std::move(d));
      }
    }
  }
  return ok;
}

bool check_weak_incident_arcs(const Rule& r, int i, std::vector<Diagnostic>& out) {
  return weak(r, i, out, "w-I");
}

bool check_incident_arcs(const Rule& r, int i, std::vector<Diagnostic>& out) {
  bool ok = weak(r, i, out, symbol(Constraint::IncidentArcs));
  const DGraph& L = r.left();
  for (Node v : r.deleted_nodes()) {
    const auto o = arcs_with(L, L.out_arcs(v), i), in = arcs_with(L, L.in_arcs(v), i);
    if (o.size() == 1 && in.size() == 1) continue;
    ok = false;
    Diagnostic d{.code = "I-deleted-node",
                 .condition = symbol(Constraint::IncidentArcs),
                 .i = i,
                 .side = Side::L};
    d.message =
        "deleted node " + L.name(v) + " is the source of " + count_str(o.size(), "outgoing", i) +
        " and the target of " + count_str(in.size(), "incoming", i) +
        " in L; exactly one each is required, else a match leaves dangling arcs (Def. 34, Fact 1)";
    d.nodes = {L.name(v)};
    d.arcs = arc_strs(r, Side::L, o);
    for (auto& s : arc_strs(r, Side::L, in))
      if (std::find(d.arcs.begin(), d.arcs.end(), s) == d.arcs.end()) d.arcs.push_back(s);
    out.push_back(std::move(d));
  }
  return ok;
}

}  // namespace gmr::checker
