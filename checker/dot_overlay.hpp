// Checker diagnostics as highlights of a rule diagram (model/draw/rule_dot.hpp): every diagnostic
// that names nodes (or, failing that, a path) highlights them on its side (for a concrete
// diagnostic without side: the side its arcs are tagged with), with its code in the node's note and
// "code: message" as tooltip. Notes are not drawn; warnings get the warning colour.
#pragma once
#include <optional>
#include <vector>

#include "checker/diagnostic.hpp"
#include "checker/scheme_checker.hpp"
#include "model/draw/rule_dot.hpp"

namespace gmr::checker {
using draw::DotHighlight;

std::vector<DotHighlight> dot_highlights(const CheckReport& r);

}  // namespace gmr::checker
