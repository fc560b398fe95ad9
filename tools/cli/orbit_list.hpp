// The `--orbits "<0,1>,<1,2>"` option of `gmr events` and `gmr apply --events`: a list of orbit
// types (model/core/orbit_type.hpp), comma-separated.
#pragma once
#include <string>
#include <vector>

#include "model/core/orbit_type.hpp"

namespace gmr::cli {

// "<0,1>,<1,2>" -> the orbit types; "" -> none (all of them, for the callers). Throws
// Error(Usage) located at --orbits for a malformed list, with the orbit type parser's message.
std::vector<OrbitType> parse_orbit_list(const std::string& text);

}  // namespace gmr::cli
