#include "checker/rule_check.hpp"

namespace gmr::checker {
using namespace gmr::graph;
using namespace gmr::rewrite;

CheckReport check_rule(const Rule& r, bool model_completion) {
  CheckReport rep;
  rep.rule = r.name();
  rep.kind = r.kind();
  rep.n = r.dimension();
  auto& d = rep.diagnostics;
  rep.conditions.emplace_back("combinatorial", check_combinatorial(r, d));
  const auto labels = r.labels();
  for (int i : labels)
    rep.conditions.emplace_back(condition_text(symbol(Constraint::IncidentArcs), i),
                                check_incident_arcs(r, i, d));
  for (int i : labels)
    if (!(r.kind() == MapKind::OMap && i == 1))
      rep.conditions.emplace_back(condition_text(symbol(Constraint::NonOrientation), i),
                                  check_non_orientation(r, i, d));
  bool any_pair = false;
  for (int i : labels)
    for (int j : labels) any_pair = any_pair || j >= i + 2;
  if (!any_pair) return rep;
  const Rule c = model_completion ? complete_for_model(r, &d) : r;
  for (int i : labels)
    for (int j : labels)
      if (j >= i + 2)
        rep.conditions.emplace_back(condition_text(symbol(Constraint::Cycle), i, j),
                                    check_cycle(c, i, j, d));
  return rep;
}

}  // namespace gmr::checker
