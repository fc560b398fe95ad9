// `gmr dot` on rule files: concrete rules and rule schemes (gmr.rule JSON, .jme) drawn by
// model/draw/rule_dot.hpp, optionally with κ arcs, the checker's diagnostics or the static events
// of one orbit type (checker/events/event_dot.hpp) overlaid. Called by tools/cli/cmd_dot.cpp before
// its map path.
#pragma once
#include <optional>
#include <string>

namespace gmr::cli {

struct RuleDotArgs {
  std::string input, output = "-", to, rule, name;
  bool kappa = false;  // κ arcs (concrete rules)
  bool check = false;  // overlay the checker's diagnostics
  std::string
      events;  // rule schemes: overlay the static events of this orbit type (checker/events)
};

// nullopt when the input is not a rule file; otherwise the exit code (0). Bad input throws.
std::optional<int> dot_rule_input(const RuleDotArgs& a);

}  // namespace gmr::cli
