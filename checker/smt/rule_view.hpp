// A concrete rule (model/rewrite/rule.hpp) as the condition plug-in interface sees it
// (condition_api.hpp): names, statuses, arcs with their status (Assumption 4).
#pragma once
#include "checker/smt/condition_api.hpp"
#include "model/rewrite/rule.hpp"

namespace gmr::smt {

condition::RuleView to_view(const rewrite::Rule& r);

}  // namespace gmr::smt
