// Events of concrete rules through their scheme on <> (concrete_scheme.hpp): the conversion gives
// the concrete rule's application back (dart for dart against the DPO of model/rewrite/dpo.hpp),
// and its static events with confirmation agree with the dynamic detector.
#include "checker/events/concrete_scheme.hpp"

#include <gtest/gtest.h>

#include "checker/events/tests/events_fixtures.hpp"
#include "model/core/error.hpp"
#include "model/rewrite/dpo.hpp"
#include "model/rule_io/rule_json.hpp"

using namespace gmr;
using namespace gmr::events;
using namespace gmr::events::testing;

namespace {
rewrite::Rule concrete_rule(const std::string& file) {
  return io::read_rule_file(source_dir() / "checker/tests/data" / file);
}
}  // namespace

// The concrete 2-unsewing of one edge (4 darts, Fig. 3.19a reversed): one hook (L is connected),
// nodes on <>, the 0- and 2-links as explicit arcs (2-loops in R).
TEST(ConcreteScheme, UnsewIsASchemeOnTheEmptyOrbitType) {
  const auto s = scheme_of_concrete_rule(concrete_rule("F5_fig319a_unsew.json"));
  EXPECT_EQ(s.orbit.size(), 0u);
  EXPECT_EQ(s.hooks, (std::vector<std::string>{"a"}));
  ASSERT_EQ(s.left.size(), 4u);
  EXPECT_EQ(s.left.arcs.size(), 4u);   // a-b 0, c-d 0, a-c 2, b-d 2
  EXPECT_EQ(s.right.arcs.size(), 6u);  // a-b 0, c-d 0, four 2-loops
  for (const auto& n : s.left.nodes) EXPECT_EQ(n.label.size(), 0u);
  // <0,2>: the edge {a,b,c,d} is complete and falls into the two complete halves {a,b}, {c,d}.
  const StaticEvents st = analyse(s, {OrbitType{0, 2}});
  ASSERT_EQ(st.orbits[0].events.size(), 1u);
  EXPECT_EQ(st.orbits[0].events[0].kind, PatternEventKind::ExplicitSplit);
  EXPECT_EQ(st.orbits[0].events[0].certainty, Certainty::Certain);
}

// Applied at an interior edge of the 2x2 grid of quads: the result is the DPO's, dart for dart, and
// the log agrees with the dynamic detector on every orbit type (Fig. 7a -> 7b, as the scheme F2).
TEST(ConcreteScheme, UnsewOnTheGridAgreesWithDpoAndOracle) {
  const rewrite::Rule r = concrete_rule("F5_fig319a_unsew.json");
  EmbeddedMap m = io::read_off_file(event_data("quad_grid_2x2.off"));
  Map& g = m.map;
  const Dart a = edge_dart(m, {1, 1, 0}, {1, 2, 0});
  const std::vector<Dart> match = {a, g.alpha(0, a), g.alpha(2, a),
                                   g.alpha(0, g.alpha(2, a))};  // a b c d
  const rewrite::MapDerivation dpo = rewrite::apply(r, g, match);
  const Checked c = apply_checked(scheme_of_concrete_rule(r), g, {a});
  expect_oracle_agrees(c);
  EXPECT_EQ(c.logged.application.match, match);
  for (int i = 0; i <= 2; ++i) EXPECT_EQ(g.links(i), dpo.H.links(i)) << i;
  EXPECT_EQ(count(c.log("<0,2>"), OrbitEventKind::Split, EventStatus::Certain), 1u);
  EXPECT_EQ(count(c.log("<1,2>"), OrbitEventKind::Split, EventStatus::Confirmed), 1u);  // (1,2)
  EXPECT_EQ(count(c.log("<0,1,2>"), OrbitEventKind::Split), 0u);
}

// A rule with two L components gets one hook per component; a rule on O-maps is refused.
TEST(ConcreteScheme, HooksPerComponentAndOMapsRefused) {
  const auto s = scheme_of_concrete_rule(concrete_rule("F5_fig319a_sew.json"));
  EXPECT_EQ(s.hooks.size(), 2u);
  EXPECT_THROW(scheme_of_concrete_rule(concrete_rule("omap_face_split.json")), Error);
}
