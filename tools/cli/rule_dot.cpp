#include "tools/cli/rule_dot.hpp"

#include "checker/dot_overlay.hpp"
#include "checker/events/event_dot.hpp"
#include "checker/rule_check.hpp"
#include "checker/scheme_checker.hpp"
#include "model/core/error.hpp"
#include "model/draw/render.hpp"
#include "model/draw/rule_dot.hpp"
#include "tools/cli/cli.hpp"
#include "tools/cli/rule_input.hpp"

namespace gmr::cli {
using namespace gmr::draw;
using namespace gmr::checker;

std::optional<int> dot_rule_input(const RuleDotArgs& a) {
  if (!is_rule_file(a.input)) {
    if (!a.rule.empty() || a.kappa || a.check || !a.events.empty())
      throw Error(ErrorCode::Usage,
                  "--rule, --kappa, --check and --events apply to rule files (gmr.rule JSON, .jme)",
                  a.input);
    return std::nullopt;
  }
  const Format out = drawing_format(a.output, a.to);
  const RuleInput in = load_rule_input(a.input, a.rule);
  RuleDotOptions opt;
  opt.kappa = a.kappa;
  opt.name = a.name;
  std::string dot;
  if (in.is_scheme()) {
    if (a.kappa)
      throw Error(ErrorCode::Usage, "--kappa draws the joint representation of a concrete rule",
                  a.input);
    if (a.check && !a.events.empty())
      throw Error(ErrorCode::Usage, "give either --check or --events", "--events");
    if (a.check) opt.highlights = dot_highlights(check_scheme(*in.scheme));
    if (!a.events.empty()) {
      const OrbitType o = OrbitType::parse(a.events);
      const events::StaticEvents st = events::analyse(*in.scheme, {o});
      opt.highlights = events::dot_highlights(*in.scheme, st.orbits[0]);
    }
    dot = to_dot(*in.scheme, opt);
  } else {
    if (!a.events.empty())
      throw Error(ErrorCode::Usage,
                  "--events draws the static events of a rule scheme, not of a concrete rule",
                  "--events");
    if (a.check) opt.highlights = dot_highlights(check_rule(*in.concrete));
    dot = to_dot(*in.concrete, opt);
  }
  write_drawing(a.output, dot, out);
  return kExitOk;
}

}  // namespace gmr::cli
