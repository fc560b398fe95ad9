// Text and JSON of the static events of a rule scheme and of the event log of an application,
// format "gmr.events", version 1 (docs/events.md):
//   {"format": "gmr.events", "version": 1, "kind": "static", "rule": ..., "dimension": n,
//    "orbits": [{"orbit": "<1>", "left": [pattern orbit], "right": [...], "events": [...]}]}
//   {"format": "gmr.events", "version": 1, "kind": "log", "rule": ..., "hooks": [...],
//    "orbits": [{"orbit": "<1>", "traversed": t, "events": [...], "checks": [...]}]}
//   {"format": "gmr.events", "version": 1, "kind": "log-set", "rule": ..., "applications": [log,
//   ...]}
//     the logs of repeated applications (apply everywhere), in order; log k names the darts of the
//     map after the applications before it.
// Positions k of implicit events are counted from 1, as the paper's "k-th implicit link".
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "checker/events/event_log.hpp"
#include "checker/events/static_events.hpp"

namespace gmr::events {

inline constexpr const char* kEventsFormat = "gmr.events";
inline constexpr int kEventsVersion = 1;

nlohmann::ordered_json static_events_to_json(const scheme::RuleScheme& s, const StaticEvents& st);
std::string static_events_to_text(const scheme::RuleScheme& s, const StaticEvents& st);

nlohmann::ordered_json event_log_to_json(const scheme::RuleScheme& s, const StaticEvents& st,
                                         const EventLog& log);
std::string event_log_to_text(const EventLog& log);
nlohmann::ordered_json event_logs_to_json(const scheme::RuleScheme& s, const StaticEvents& st,
                                          const std::vector<EventLog>& logs);

// "implicit split along 2 of L<1>(n0) -> R<1>(n0), possible: compare m(b,n0), m(b+2,n0) on H".
std::string describe(const scheme::RuleScheme& s, const OrbitTypeEvents& t, const PatternEvent& e);

}  // namespace gmr::events
