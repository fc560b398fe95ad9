// Events of one transformation t : G => H on the orbits of one orbit type <o> (Gaide et al. 2023,
// §3), orbits named by their lowest dart identifier (§5). Darts alive in G and in H are preserved
// (the application engine keeps their identifiers), darts alive in H only are created, in G only
// deleted.
//  * creation: an H-orbit of created darts only (Def. 3.1.1);
//  * deletion: a G-orbit of deleted darts only (Def. 3.4.1);
//  * split: a G-orbit whose preserved darts lie in several H-orbits (Def. 3.2.1);
//  * merge: an H-orbit whose preserved darts come from several G-orbits (Def. 3.3.1);
//  * non-modification: G<o>(d) = H<o>(d), darts and links (Def. 3.4.2);
//  * modification: any other G-orbit with preserved darts, neither split nor merged (§3.4.3).
// An orbit can be split and merged by one transformation (Fig. 1c): both events are listed.
#pragma once
#include <string>
#include <tuple>
#include <vector>

#include "checker/events/dart_list.hpp"
#include "model/core/map.hpp"
#include "model/core/orbit_type.hpp"

namespace gmr::events {

enum class OrbitEventKind { Creation, Deletion, Split, Merge, Modification, NonModification };
const char* to_string(OrbitEventKind k);

// How the event was established at application time.
enum class EventStatus {
  Certain,    // decided by the static analysis alone
  Confirmed,  // a possible split or merge, confirmed on its instance pairs
  Refuted,  // a (non-)modification where a possible split or merge was not confirmed, or where the
            // static verdict, modification, was refuted by the links (a loop rewritten into itself)
  Observed,  // found by comparing all orbits (the dynamic detector)
};
const char* to_string(EventStatus s);

struct OrbitEvent {
  OrbitEventKind kind = OrbitEventKind::Modification;
  DimMask orbit = 0;  // the orbit type's dimensions (a mask: no allocation per event)
  DartList before;    // G-orbits (lowest ids, increasing); empty for a creation
  DartList after;     // H-orbits (lowest ids, increasing); empty for a deletion
  EventStatus status = EventStatus::Observed;

  // The event without its status, for comparisons.
  auto key() const { return std::tie(kind, before, after); }
  // "Split G<0,1>(a) -> {H<0,1>(b), H<0,1>(c)}" with darts as numbers.
  std::string describe() const;
};

// Sorts events by (kind, before, after): two detectors' lists compare with ==.
void sort_events(std::vector<OrbitEvent>& events);
bool same_events(std::vector<OrbitEvent> a, std::vector<OrbitEvent> b);

}  // namespace gmr::events
