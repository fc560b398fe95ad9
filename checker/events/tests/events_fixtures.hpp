// Shared by the event tests: data files, one application logged by the static analysis with
// confirmation and, on a copy of G, compared with the dynamic detector for every orbit type.
#pragma once
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "checker/events/dynamic_events.hpp"
#include "checker/events/event_log.hpp"
#include "checker/events/static_events.hpp"
#include "model/core/orbit.hpp"
#include "model/core/position.hpp"
#include "model/map_io/map_json.hpp"
#include "model/map_io/off.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "model/testing/source_tree.hpp"

namespace gmr::events::testing {

inline std::filesystem::path source_dir() { return gmr::testing::source_path("."); }
inline scheme::RuleScheme library_rule(const std::string& name) {
  return io::read_scheme_file(source_dir() / "tools/data/rules" / (name + ".json"));
}
inline std::filesystem::path event_data(const std::string& name) {
  return source_dir() / "checker/events/tests/data" / name;
}

struct LoggedApplication {
  scheme::SchemeApplication application;
  EventLog log;  // empty orbits when the scheme was not applied
};

// Applies `engine` at `hooks` in g with the event log of `analysis` (EventRecorder).
inline LoggedApplication apply_logged(const scheme::SchemeEngine& engine,
                                      const StaticEvents& analysis, Map& g,
                                      const std::vector<Dart>& hooks) {
  EventRecorder recorder(engine.scheme(), analysis);
  LoggedApplication out{scheme::apply(engine, g, hooks, &recorder), {}};
  if (out.application) out.log = std::move(recorder.logs().back());
  return out;
}

// A logged application and the dynamic detector's verdict for each analysed orbit type.
struct Checked {
  LoggedApplication logged;
  std::vector<std::vector<OrbitEvent>> dynamic;  // touched orbits only, per orbit type
  const OrbitTypeLog& log(const std::string& o) const {
    for (const auto& t : logged.log.orbits)
      if (t.orbit.str() == o) return t;
    throw std::runtime_error("no orbit type " + o);
  }
};

// Applies `s` at `hooks` on g (in place) with the event log, and the dynamic detector on the same
// application; every orbit type of dimension n is analysed.
inline Checked apply_checked(const scheme::RuleScheme& s, Map& g, const std::vector<Dart>& hooks) {
  const StaticEvents st = analyse(s);
  std::vector<OrbitSnapshot> before;
  for (const auto& t : st.orbits) before.push_back(snapshot(g, t.orbit));
  const scheme::SchemeEngine engine(s);
  Checked c{apply_logged(engine, st, g, hooks), {}};
  if (!c.logged.application) return c;
  for (size_t t = 0; t < st.orbits.size(); ++t)
    c.dynamic.push_back(dynamic_events(before[t], g, &c.logged.application.match));
  return c;
}

inline std::string describe(const std::vector<OrbitEvent>& es) {
  std::string s;
  for (const auto& e : es) s += "  " + e.describe() + " [" + to_string(e.status) + "]\n";
  return s;
}

// The log agrees with the dynamic detector on every orbit type.
inline void expect_oracle_agrees(const Checked& c) {
  ASSERT_TRUE(c.logged.application) << c.logged.application.why;
  for (size_t t = 0; t < c.dynamic.size(); ++t)
    EXPECT_TRUE(same_events(c.logged.log.orbits[t].events, c.dynamic[t]))
        << c.logged.log.orbits[t].orbit.str() << "\nlog:\n"
        << describe(c.logged.log.orbits[t].events) << "dynamic:\n"
        << describe(c.dynamic[t]);
}

// Number of events of a kind (and status, when given) in one orbit type's log.
inline size_t count(const OrbitTypeLog& l, OrbitEventKind k) {
  size_t n = 0;
  for (const auto& e : l.events) n += e.kind == k;
  return n;
}
inline size_t count(const OrbitTypeLog& l, OrbitEventKind k, EventStatus st) {
  size_t n = 0;
  for (const auto& e : l.events) n += e.kind == k && e.status == st;
  return n;
}

// (V, E, F, CC) of a 2-G-map.
inline std::vector<size_t> cells(const Map& g) {
  auto c = count_all_cells(g);
  c.push_back(count_components(g));
  return c;
}

// A dart at the vertex of position p on the edge towards position q (OFF maps).
inline Dart edge_dart(const EmbeddedMap& m, Vec3 p, Vec3 q) {
  for (Dart d : m.map.darts())
    if (m.position().get(d) == p && m.position().get(m.map.alpha(0, d)) == q) return d;
  throw std::runtime_error("no such edge");
}

}  // namespace gmr::events::testing
