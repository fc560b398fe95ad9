// The --match syntax of `gmr apply` for concrete rules: comma-separated NODE=DART pairs naming
// nodes of the left-hand side and live darts of the map, each node at most once ("a=3,b=5").
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "model/core/map.hpp"
#include "model/rewrite/rule.hpp"

namespace gmr::cli {

// Error(Usage) located "--match" naming the first bad pair.
std::vector<std::pair<graph::Node, Dart>> parse_match_pairs(const rewrite::Rule& r, const Map& g,
                                                            const std::string& text);

}  // namespace gmr::cli
