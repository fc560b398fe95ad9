// The dynamic detector (Gaide et al. 2023, §5, the baseline): every <o>-orbit of G is named before
// the transformation, every <o>-orbit of H after it, and the two partitions are compared dart by
// dart (orbit_event.hpp gives the definitions). Cost O(|G| + |H|) per orbit type, whatever the
// size of the rewritten part; the static analysis with confirmation (event_log.hpp) is checked
// against it.
#pragma once
#include <vector>

#include "checker/events/orbit_event.hpp"
#include "model/core/map.hpp"

namespace gmr::events {

// G before the transformation, for one orbit type: the lowest dart of each dart's orbit and the
// dart's <o>-links (indexed by dart; kNoDart for a dead dart).
struct OrbitSnapshot {
  OrbitType orbit;
  std::vector<Dart> name;
  std::vector<std::vector<Dart>> links;  // one array per dimension of <o>, in increasing order
};

// Throws Error(Range) for an orbit type the map does not have (require_orbit_type).
OrbitSnapshot snapshot(const Map& g, const OrbitType& o);

// Every event of the transformation from `before` to h; statuses are Observed. Non-modifications
// are listed for every unchanged orbit of G, or, when `touched` is given (G darts, e.g. the matched
// ones), only for those holding one of its darts: the orbits a rule application leaves untouched
// are not logged.
std::vector<OrbitEvent> dynamic_events(const OrbitSnapshot& before, const Map& h,
                                       const std::vector<Dart>* touched = nullptr);

}  // namespace gmr::events
