// The event log of one rule application (Gaide et al. 2023, §4): the static events of the scheme
// (static_events.hpp) instantiated on the match, the possible splits and merges confirmed on their
// instance pairs only, every orbit named by its lowest dart (§5).
//
// Procedure, per analysed orbit type <o>:
//  1. before the rewrite (G intact): every instance of an L pattern orbit is named. A complete
//     pattern orbit's instance components are whole G-orbits, named by their lowest dart without
//     leaving the match; an incomplete one is named by traversing its G-orbit (once per orbit).
//     The pairs of possible merges are compared there: merges are confirmed on G, before the
//     darts change (the paper says "on G" for splits too, Props. 3.2.1/3.3.1: a split can only be
//     seen on H).
//  2. the engine rewrites G into H (model/scheme/scheme_engine.hpp).
//  3. after it: the instances of R pattern orbits are named the same way on H, and the pairs of
//     possible splits are compared there.
//  4. the log: creations and deletions of the created / deleted pattern orbits; a split for every
//     G-orbit where a flagged pair lies in two H-orbits, listing the H-orbits of all its preserved
//     matched darts; a merge for every H-orbit where a flagged pair comes from two G-orbits; every
//     other G-orbit holding matched darts is not modified when none of its matched darts is deleted
//     and none of their <o>-links changed, else modified (§3.4.2–3.4.3). The static verdict of
//     Def. 3.4.2 is not used for this last choice: on a hook orbit where position k is an i-loop,
//     a label change at k can rewrite an i-loop into the same i-loop, and the orbit is unchanged
//     although the pattern orbit is modified; comparing the links of the matched darts stays
//     inside the match.
// Orbits holding no matched dart are not logged: the rule leaves them unchanged (Prop. 3.4.2).
// Cost: the match and comatch tables times the number of orbit types, plus one traversal per
// G- or H-orbit of an incomplete pattern orbit (the whole component for <0,..,n>), however many
// instance components of however many pattern orbits it holds.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "checker/events/orbit_event.hpp"
#include "checker/events/static_events.hpp"
#include "model/scheme/scheme_engine.hpp"

namespace gmr::events {

// One comparison of an instance pair of a possible split (on H) or merge (on G).
struct PairCheck {
  uint32_t event = 0;  // index in OrbitTypeEvents::events
  char map = 'G';      // 'G' before the rewrite (merges), 'H' after it (splits)
  Dart a = kNoDart, b = kNoDart;
  bool different = false;  // the two darts lie in different orbits: the event holds there
};

struct OrbitTypeLog {
  OrbitType orbit;
  // Creations and deletions (in the order of the pattern events and of the instances), merges (by
  // name), then splits, modifications and non-modifications by G-orbit name.
  std::vector<OrbitEvent> events;
  std::vector<PairCheck> checks;
  size_t traversed = 0;  // darts visited by the traversals of incomplete instances
};

struct EventLog {
  std::string rule;
  std::vector<Dart> hooks;
  std::vector<OrbitTypeLog> orbits;  // in the order of StaticEvents::orbits
};

// The event log as an application observer (model/scheme/scheme_engine.hpp), passed to
// scheme::apply or scheme::apply_everywhere (model/scheme/apply_everywhere.hpp): it logs every
// application it sees, one EventLog per successful application, in order, each naming the orbits
// of the map just before and just after that application, with the application's hook darts.
// `analysis` (its orbit types) must be the static events of `s`, else Error(Usage). `also` (e.g.
// the embedding propagation of model/expr) observes the applications too. The scheme and the
// analysis must outlive the recorder.
class EventRecorder : public scheme::ApplicationObserver {
 public:
  EventRecorder(const scheme::RuleScheme& s, const StaticEvents& analysis,
                scheme::ApplicationObserver* also = nullptr);
  ~EventRecorder() override;
  void before_rewrite(const Map& g, const scheme::SchemeApplication& app,
                      const scheme::OrbitGraph& O) override;
  void after_rewrite(const Map& g, const scheme::SchemeApplication& app,
                     const scheme::OrbitGraph& O) override;
  std::vector<EventLog>& logs() { return logs_; }

 private:
  struct Impl;
  const scheme::RuleScheme& s_;
  std::vector<uint32_t> hook_nodes_;  // L node of each hook
  std::unique_ptr<Impl> impl_;
  scheme::ApplicationObserver* also_;
  std::vector<EventLog> logs_;
};

}  // namespace gmr::events
