// A concrete rule (model/rewrite/rule.hpp) as a rule scheme on the orbit type <> (thesis §4.5, Def.
// 46 with the empty orbit type): the hook orbit is one dart, so every scheme node is one dart, with
// no implicit link; the concrete arcs become explicit arcs. Instantiating it (model/scheme) gives
// the concrete rule back, so the events of the concrete rule are the static events of this scheme
// (Gaide et al. 2023 §3: a pattern orbit is then made of explicit arcs only).
//
// Nodes keep their names (preserved nodes share a name, as in the concrete rule); an i-link of the
// D-graph (the arcs a -i-> b and b -i-> a, or one i-loop) is one explicit arc. Hooks: the first
// node, in L order, of every connected component of L (the engine propagates the match from them
// along explicit arcs). A rule without L nodes has no hook (it only creates).
//
// Throws Error(Usage) for an O-map rule (rule schemes rewrite G-maps).
#pragma once
#include "model/rewrite/rule.hpp"
#include "model/scheme/rule_scheme.hpp"

namespace gmr::events {

scheme::RuleScheme scheme_of_concrete_rule(const rewrite::Rule& r);

}  // namespace gmr::events
