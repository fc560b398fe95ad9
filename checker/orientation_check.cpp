// Non-orientation condition O_r(i), Def. 37: any deleted (resp. added) i-arc has a unique reverse
// i-arc that is also deleted (resp. added). A loop is its own reverse.
#include "checker/rule_check.hpp"

namespace gmr::checker {
using namespace gmr::graph;
using namespace gmr::rewrite;

bool check_non_orientation(const Rule& r, int i, std::vector<Diagnostic>& out) {
  bool ok = true;
  for (Side side : {Side::L, Side::R}) {
    const DGraph& g = r.side(side);
    const ElemStatus changed = side == Side::R ? ElemStatus::Added : ElemStatus::Deleted;
    for (ArcId a : g.arc_slots()) {
      if (!g.arc_alive(a) || g.arc(a).label != i || r.arc_status(side, a) != changed) continue;
      const Arc& e = g.arc(a);
      std::vector<ArcId> rev;
      for (ArcId b : g.out_arcs(e.tgt))
        if (g.arc(b).label == i && g.arc(b).tgt == e.src) rev.push_back(b);
      Diagnostic d{.condition = symbol(Constraint::NonOrientation),
                   .i = i,
                   .side = side,
                   .nodes = {g.name(e.src), g.name(e.tgt)},
                   .arcs = {r.arc_str(side, a)}};
      const std::string what = std::string(to_string(changed)) + " arc " + r.arc_str(side, a);
      if (rev.empty()) {
        d.code = "O-no-reverse";
        d.message = "the " + what + " has no reverse " + std::to_string(i) + "-arc in " +
                    to_string(side) + " (Def. 37)";
      } else if (rev.size() > 1) {
        d.code = "O-several-reverses";
        d.message = "the " + what + " has " + std::to_string(rev.size()) +
                    " reverse arcs; a unique one is required (Def. 37)";
        for (ArcId b : rev) d.arcs.push_back(r.arc_str(side, b));
      } else if (r.arc_status(side, rev[0]) != changed) {
        d.code = "O-status-mismatch";
        d.message = "the " + what + " has the " + to_string(r.arc_status(side, rev[0])) +
                    " reverse " + r.arc_str(side, rev[0]) + "; both must be " + to_string(changed) +
                    " (Def. 37)";
        d.arcs.push_back(r.arc_str(side, rev[0]));
      } else {
        continue;
      }
      ok = false;
      out.push_back(std::move(d));
    }
  }
  return ok;
}

}  // namespace gmr::checker
