// `gmr apply` for rule schemes (issue 4): the application engine (model/scheme_engine.hpp) at the
// given hook dart(s), or at every dart where the scheme applies (--all). Called by
// tools/cli/cmd_apply.cpp when the rule file is a scheme (gmr.rule kind "scheme" or .jme).
//
// --all (schemes with one hook): Jerboa-style repeated application. The darts of the input map are
// visited in increasing order; at each dart not yet used by an application (as a matched dart), the
// scheme is applied with that dart as a fresh hook when it applies; the matched darts of every
// application are then used. Darts created by an application are never hooks. E.g. quad subdivision
// (orbit <0,1,2>) is applied once per connected component, vertex insertion on <0> once per edge.
#pragma once
#include <string>

#include "model/scheme/rule_scheme.hpp"

namespace gmr::cli {
using scheme::RuleScheme;

struct SchemeApplyArgs {
  std::string rule, input, from, output, to, hooks;
  bool all = false, json = false;
};

// Exit 0 when applied and the result is a valid map (written to -o when given), 1 when the scheme
// does not apply (the reason is printed) or the result is not a valid map; bad input throws.
int apply_scheme_input(const RuleScheme& s, const SchemeApplyArgs& a);

}  // namespace gmr::cli
