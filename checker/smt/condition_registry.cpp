#include "checker/smt/condition_registry.hpp"

#include "checker/rule_check.hpp"

namespace gmr::smt {
using rewrite::Rule;

bool thesis_conditions(const Rule& r, const ThesisParts& parts) {
  std::vector<checker::Diagnostic> d;
  if (!checker::check_combinatorial(r, d)) return false;
  const MapSpec spec = r.spec();
  for (int i : spec.labels())
    if (!(parts.dangling ? checker::check_incident_arcs(r, i, d)
                         : checker::check_weak_incident_arcs(r, i, d)))
      return false;
  if (parts.orientation)
    for (int i : spec.labels())
      if (spec.is_involutive_dim(i) && !checker::check_non_orientation(r, i, d)) return false;
  const auto pairs = spec.cycle_pairs();
  if (pairs.empty()) return true;
  const Rule c = parts.completion ? checker::complete_for_model(r) : r;
  for (auto [i, j] : pairs)
    if (!(parts.completion ? checker::check_cycle(c, i, j, d)
                           : checker::check_cycle_as_written(c, i, j, d)))
      return false;
  return true;
}

const std::vector<BuiltinCondition>& builtin_conditions() {
  static const std::vector<BuiltinCondition> all = {
      {"thesis",
       "Theorems 1-3 for the rule's model: combinatorial, I_r, O_r, C_r on the model completion",
       [](const Rule& r) { return checker::check_rule(r).ok(); }},
      {"thesis-per-constraint", "Theorems 1-3 with C_r on the ij-completion only (no O-completion)",
       [](const Rule& r) { return checker::check_rule(r, false).ok(); }},
      {"wrong-incident-without-dangling", "WRONG: w-I_r instead of I_r (the dangling part dropped)",
       [](const Rule& r) { return thesis_conditions(r, {.dangling = false}); }},
      {"wrong-cycle-without-completion", "WRONG: C_r on the rule as written, without ij-completion",
       [](const Rule& r) { return thesis_conditions(r, {.completion = false}); }},
      {"wrong-orientation-dropped", "WRONG: the non-orientation condition O_r dropped",
       [](const Rule& r) { return thesis_conditions(r, {.orientation = false}); }},
  };
  return all;
}

const BuiltinCondition* find_builtin_condition(const std::string& name) {
  for (const auto& c : builtin_conditions())
    if (c.name == name) return &c;
  return nullptr;
}

}  // namespace gmr::smt
