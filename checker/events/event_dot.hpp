// Static events drawn on a rule diagram (model/draw/rule_dot.hpp): for one orbit type, the nodes
// of every pattern orbit taking part in a creation, deletion, split, merge or modification are
// highlighted — possible events (to confirm at application time) in the warning colour, certain
// ones in the error colour — with a short code in the node's note ("S2?" = implicit split along
// position 2, possible; "S" explicit split; "M"/"M1?" merges; "C" creation; "D" deletion; "mod"
// modification) and the event's description as tooltip. Non-modifications are not drawn.
#pragma once
#include <vector>

#include "checker/events/static_events.hpp"
#include "model/draw/rule_dot.hpp"

namespace gmr::events {

std::vector<draw::DotHighlight> dot_highlights(const scheme::RuleScheme& s,
                                               const OrbitTypeEvents& t);

}  // namespace gmr::events
