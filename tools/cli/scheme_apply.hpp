// `gmr apply` for rule schemes: the application engine (model/scheme/scheme_engine.hpp) at the
// given hook dart(s), or at every dart where the scheme applies (--all, schemes with one hook:
// model/scheme/apply_everywhere.hpp). Called by tools/cli/cmd_apply.cpp when the rule file is a
// scheme (gmr.rule kind "scheme" or .jme). This file handles the arguments and the printing only.
// Embeddings: the map's embeddings go through the application with the scheme's expressions
// (model/expr/propagation.hpp); --no-embeddings drops them first (topology only).
#pragma once
#include <string>

#include "model/scheme/rule_scheme.hpp"

namespace gmr::cli {
using scheme::RuleScheme;

struct SchemeApplyArgs {
  std::string rule, input, from, output, to, hooks;
  bool all = false, json = false, lift = false;
  size_t limit = 20;  // violations of the result listed
  bool no_embeddings = false;
  std::string events;  // event log file (gmr.events: kind log at --hook, log-set with --all)
  std::string orbits;  // the orbit types logged ("<0,1>,<1,2>"; all when empty), with events only
};

// With `events`, the application at the hooks is logged (checker/events/event_log.hpp: static
// events confirmed on the match, every orbit type or those of `orbits`) and the log written there
// atomically; with --all, every application is logged, in order, in one document of kind
// "log-set" (each log names the darts of the map just before and after its application).
// Exit 0 when applied and the result is a valid map with consistent embeddings (written to -o when
// given), 1 when the scheme does not apply (the reason is printed), the result is not a valid map,
// or an embedding is not consistent (E-no-value, E-merge, E-overlap, listed); bad input throws.
int apply_scheme_input(const RuleScheme& s, const SchemeApplyArgs& a);

}  // namespace gmr::cli
