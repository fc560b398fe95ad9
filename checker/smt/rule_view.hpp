// A concrete rule (model/rewrite/rule.hpp) as the condition plug-in interface sees it
// (condition_api.hpp): names, statuses, arcs with their status (Assumption 4).
#pragma once
#include "checker/smt/condition_api.hpp"
#include "model/rewrite/rule.hpp"
#include "model/scheme/rule_scheme.hpp"

namespace gmr::smt {

condition::RuleView to_view(const rewrite::Rule& r);
// A rule scheme as the scheme-condition interface sees it.
condition::SchemeView to_view(const scheme::RuleScheme& s);

}  // namespace gmr::smt
