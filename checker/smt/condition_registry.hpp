// Conditions on concrete rules validated by `gmr validate-condition` (docs/verify.md): built-in
// ones, registered by name, and plug-ins (condition_plugin.hpp).
//
// Built-in conditions (the model's conditions of §3.4, i.e. Theorems 1-3 for every label and pair
// of the rule's model, G-maps or O-maps, as checker/rule_check.hpp evaluates them):
//   thesis                          check_rule: combinatorial (Def. 35), I_r (Def. 34) on every
//                                   label, O_r (Def. 37) on the involutive labels, C_r (Def. 40)
//                                   on the cycle pairs of the model completion;
//   thesis-per-constraint           the same with C_r on the ij-completion only (no O-completion);
// and three deliberately wrong variants, which the validation must refute:
//   wrong-incident-without-dangling w-I_r (Def. 33) instead of I_r: the dangling part dropped;
//   wrong-cycle-without-completion  C_r on the rule as written, no ij-completion (Assumption 5);
//   wrong-orientation-dropped       no O_r.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "model/rewrite/rule.hpp"

namespace gmr::smt {

struct BuiltinCondition {
  std::string name;
  std::string description;
  std::function<bool(const rewrite::Rule&)> holds;
};

const std::vector<BuiltinCondition>& builtin_conditions();
// nullptr when no built-in condition has that name.
const BuiltinCondition* find_builtin_condition(const std::string& name);

// The conjunction of the thesis conditions with parts switched off (the wrong variants).
struct ThesisParts {
  bool dangling = true;     // I_r rather than w-I_r
  bool orientation = true;  // O_r
  bool completion = true;   // C_r on the model completion rather than on the rule as written
};
bool thesis_conditions(const rewrite::Rule& r, const ThesisParts& parts = {});

}  // namespace gmr::smt
