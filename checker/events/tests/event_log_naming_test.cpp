// Naming the instances of incomplete pattern orbits (checker/events/event_log.hpp, docs/events.md,
// "Run time"): one traversal per orbit of the map, whatever the number of instance components and
// of incomplete pattern orbits it holds, and the names equal to the dynamic detector's.
#include <gtest/gtest.h>

#include "checker/events/tests/events_fixtures.hpp"
#include "model/core/builders.hpp"
#include "model/rule_io/jme_import.hpp"

using namespace gmr;
using namespace gmr::events;
using namespace gmr::events::testing;

namespace {

scheme::RuleScheme jerboa_rule(const std::string& name) {
  for (auto& r :
       io::read_jme_file(source_dir() / "tools/data/jerboa/JerboaTrackingOrbit.jme").rules)
    if (r.name == name) return r;
  throw std::runtime_error("no Jerboa rule " + name);
}

// A stack of three cubes; MergeHFaces at a dart of the shared face of the two lowest.
struct Stack {
  Map g = make_polycube({{0, 0, 0}, {0, 0, 1}, {0, 0, 2}});
  Dart hook = kNoDart;
  Stack() {
    for (Dart d : g.darts())
      if (!g.is_free(3, d)) {
        hook = d;
        break;
      }
  }
};

}  // namespace

// Every orbit type of the 3-G-map: the log equals the dynamic detector's events.
TEST(EventLogNaming, MergeOfStackedCubesAgreesWithTheDynamicDetector) {
  Stack s;
  const Checked c = apply_checked(jerboa_rule("MergeHFaces"), s.g, {s.hook});
  expect_oracle_agrees(c);
  EXPECT_EQ(count(c.log("<0,1,2>"), OrbitEventKind::Merge, EventStatus::Certain) +
                count(c.log("<0,1,2>"), OrbitEventKind::Merge, EventStatus::Confirmed),
            1u)
      << describe(c.log("<0,1,2>").events);
}

// <0,1,2,3> is one incomplete pattern orbit on each side whose instance components (one per orbit
// index b outside its positions) all lie in the single connected component: it is traversed once
// on G (144 darts) and once on H (112 darts: the 32 darts of the shared face are deleted), not once
// per component.
TEST(EventLogNaming, TheComponentIsTraversedOncePerSide) {
  Stack s;
  const auto rule = jerboa_rule("MergeHFaces");
  const StaticEvents st = analyse(rule, {OrbitType{0, 1, 2, 3}});
  ASSERT_FALSE(st.orbits[0].left.complete[0]);
  const scheme::SchemeEngine engine(rule);
  ASSERT_EQ(s.g.size(), 144u);
  const LoggedApplication la = apply_logged(engine, st, s.g, {s.hook});
  ASSERT_TRUE(la.application) << la.application.why;
  EXPECT_EQ(s.g.size(), 112u);
  EXPECT_EQ(la.log.orbits[0].traversed, 144u + 112u);
}

// Incomplete pattern orbits on the face type <0,1>: the faces around the deleted one are named by
// traversal, each traversed once per side; a second application on the same kind of map reuses the
// working buffers of the first and gives the same log.
TEST(EventLogNaming, RepeatedApplicationsGiveTheSameLog) {
  const auto rule = jerboa_rule("MergeHFaces");
  const StaticEvents st = analyse(rule, {OrbitType{0, 1}});
  const scheme::SchemeEngine engine(rule);
  Stack a, b;
  const LoggedApplication first = apply_logged(engine, st, a.g, {a.hook});
  const LoggedApplication second = apply_logged(engine, st, b.g, {b.hook});
  ASSERT_TRUE(first.application && second.application);
  EXPECT_GT(first.log.orbits[0].traversed, 0u);
  EXPECT_EQ(first.log.orbits[0].traversed, second.log.orbits[0].traversed);
  EXPECT_TRUE(same_events(first.log.orbits[0].events, second.log.orbits[0].events));
}
