#include "checker/events/orbit_event.hpp"

#include <algorithm>

namespace gmr::events {

const char* to_string(OrbitEventKind k) {
  switch (k) {
    case OrbitEventKind::Creation:
      return "creation";
    case OrbitEventKind::Deletion:
      return "deletion";
    case OrbitEventKind::Split:
      return "split";
    case OrbitEventKind::Merge:
      return "merge";
    case OrbitEventKind::Modification:
      return "modification";
    case OrbitEventKind::NonModification:
      return "non-modification";
  }
  return "?";
}

const char* to_string(EventStatus s) {
  switch (s) {
    case EventStatus::Certain:
      return "certain";
    case EventStatus::Confirmed:
      return "confirmed";
    case EventStatus::Refuted:
      return "refuted";
    case EventStatus::Observed:
      return "observed";
  }
  return "?";
}

namespace {
// "<0,1>" from the mask.
std::string orbit_text(DimMask m) {
  std::string s = "<";
  for (int i = 0; m >> i; ++i)
    if ((m >> i) & 1u) s += (s.size() > 1 ? "," : "") + std::to_string(i);
  return s + ">";
}

std::string names(char side, DimMask m, const DartList& ds, bool braces) {
  const std::string o = orbit_text(m);
  std::string s = braces ? "{" : "";
  for (size_t k = 0; k < ds.size(); ++k)
    s += (k ? ", " : "") + std::string(1, side) + o + "(" + std::to_string(ds[k]) + ")";
  return s + (braces ? "}" : "");
}
}  // namespace

std::string OrbitEvent::describe() const {
  switch (kind) {
    case OrbitEventKind::Creation:
      return "Creation " + names('H', orbit, after, false);
    case OrbitEventKind::Deletion:
      return "Deletion " + names('G', orbit, before, false);
    case OrbitEventKind::Split:
      return "Split " + names('G', orbit, before, false) + " -> " + names('H', orbit, after, true);
    case OrbitEventKind::Merge:
      return "Merge " + names('G', orbit, before, true) + " -> " + names('H', orbit, after, false);
    case OrbitEventKind::Modification:
      return "Modif " + names('G', orbit, before, false) + " -> " + names('H', orbit, after, false);
    case OrbitEventKind::NonModification:
      return "No modif " + names('H', orbit, after, false);
  }
  return "?";
}

void sort_events(std::vector<OrbitEvent>& events) {
  std::sort(events.begin(), events.end(),
            [](const OrbitEvent& a, const OrbitEvent& b) { return a.key() < b.key(); });
}

bool same_events(std::vector<OrbitEvent> a, std::vector<OrbitEvent> b) {
  if (a.size() != b.size()) return false;
  sort_events(a);
  sort_events(b);
  for (size_t k = 0; k < a.size(); ++k)
    if (a[k].key() != b[k].key()) return false;
  return true;
}

}  // namespace gmr::events
