// Topological events (Gaide et al. 2023): on random rule schemes accepted by the scheme checker,
// on the library (tools/data/rules and the Jerboa fixture's rules) and on random G-maps at random
// hooks — and on random concrete rules through their scheme on <> — the static analysis with its
// run-time confirmation (checker/events/event_log.hpp) logs exactly the events of the dynamic
// detector, which compares every orbit of G and H (checker/events/dynamic_events.hpp), for every
// orbit type of the dimension.
#include <gtest/gtest.h>

#include "checker/events/concrete_scheme.hpp"
#include "checker/events/dynamic_events.hpp"
#include "checker/events/event_log.hpp"
#include "checker/events/static_events.hpp"
#include "checker/scheme_checker.hpp"
#include "model/core/error.hpp"
#include "proptests/engine_or_discard.hpp"
#include "proptests/generators.hpp"
#include "proptests/harness.hpp"
#include "proptests/library.hpp"
#include "proptests/rule_cases.hpp"
#include "proptests/scheme_cases.hpp"

using namespace gmr;
using namespace gmr::scheme;
using namespace gmr::events;
using namespace gmr::prop;

namespace {

std::string listing(const std::vector<OrbitEvent>& es) {
  std::string s;
  for (const auto& e : es) s += "  " + e.describe() + " [" + to_string(e.status) + "]\n";
  return s;
}

// Tries up to `tries` random hook choices on a random map of the scheme's dimension; at the first
// application, the log and the dynamic detector must agree on every orbit type.
void log_equals_dynamic(const SchemeEngine& engine, const StaticEvents& st, size_t max_map_size,
                        int tries) {
  const RuleScheme& s = engine.scheme();
  const MapCase mc = *gen_map_case_of_dim(s.dimension, max_map_size);
  Map g = mc.build();
  RC_PRE(g.size() > 0u);
  const auto darts = g.darts();
  std::vector<OrbitSnapshot> before;
  for (const auto& t : st.orbits) before.push_back(snapshot(g, t.orbit));
  for (int attempt = 0; attempt < tries; ++attempt) {
    std::vector<Dart> hooks;
    for (size_t h = 0; h < s.hooks.size(); ++h)
      hooks.push_back(darts[*rc::gen::inRange<size_t>(0, darts.size())]);
    EventRecorder recorder(s, st);
    const SchemeApplication app = scheme::apply(engine, g, hooks, &recorder);
    if (!app) continue;
    RC_TAG("applied");
    RC_LOG() << "map " << mc.str() << ", hooks";
    for (Dart h : hooks) RC_LOG() << " " << h;
    RC_LOG() << "\n";
    for (size_t t = 0; t < st.orbits.size(); ++t) {
      const auto dyn = dynamic_events(before[t], g, &app.match);
      const auto& log = recorder.logs().back().orbits[t].events;
      if (!same_events(log, dyn)) {
        RC_LOG() << st.orbits[t].orbit.str() << "\nlog:\n"
                 << listing(log) << "dynamic:\n"
                 << listing(dyn);
        RC_FAIL("the event log differs from the dynamic detector");
      }
    }
    return;
  }
  RC_TAG("not applied");
}

void random_scheme_property(const SchemeCase& c) {
  const RuleScheme s = c.build();
  std::optional<SchemeEngine> engine;
  emplace_engine_or_discard(engine, s, "malformed");
  RC_PRE(engine->not_combinatorial().empty());
  RC_PRE(checker::check_scheme(s, {.embeddings = false}).ok());  // events are topological
  log_equals_dynamic(*engine, analyse(s), c.n == 3 ? 2 : 4, 8);
}

}  // namespace

TEST(EventProps, LogEqualsDynamicOnRandomSchemes2D) {
  EXPECT_TRUE(check_property<SchemeCase>("events_random_2d", gen_scheme_case_of_dim(2),
                                         random_scheme_property));
}

TEST(EventProps, LogEqualsDynamicOnRandomSchemes3D) {
  EXPECT_TRUE(check_property<SchemeCase>("events_random_3d", gen_scheme_case_of_dim(3),
                                         random_scheme_property));
}

TEST(EventProps, LogEqualsDynamicOnConsistentByConstructionSchemes) {
  EXPECT_TRUE(check_property<SchemeCase>("events_copies", gen_copies_scheme_case(),
                                         random_scheme_property));
}

// Every accepted library scheme (standard operations and Jerboa rules) of dimensions 2 and 3.
TEST(EventProps, LogEqualsDynamicOnTheLibrary) {
  const auto& lib = scheme_library();
  std::vector<size_t> idx = library_of_dim(2, true);
  for (size_t k : library_of_dim(3, true)) idx.push_back(k);
  ASSERT_FALSE(idx.empty());
  std::vector<StaticEvents> analyses(lib.size());
  for (size_t k : idx) analyses[k] = analyse(lib[k].scheme);
  EXPECT_TRUE(rc::check("events_library", [&] {
    const size_t k = *rc::gen::elementOf(idx);
    RC_TAG(lib[k].scheme.name);
    log_equals_dynamic(*lib[k].engine, analyses[k], lib[k].scheme.dimension == 3 ? 3 : 6, 16);
  }));
}

// Concrete rules through their scheme on <> (checker/events/concrete_scheme.hpp): random rules
// consistent by construction, on G-maps, applied where their hooks' darts match.
TEST(EventProps, LogEqualsDynamicOnConcreteRules) {
  EXPECT_TRUE(check_property<RuleCase>(
      "events_concrete", gen_consistent_rule_case(), [](const RuleCase& c) {
        const rewrite::Rule r = c.build();
        RC_PRE(r.kind() == MapKind::GMap);
        const RuleScheme s = scheme_of_concrete_rule(r);
        std::optional<SchemeEngine> engine;
        emplace_engine_or_discard(engine, s, "not a scheme the engine applies");
        RC_PRE(engine->not_combinatorial().empty());
        log_equals_dynamic(*engine, analyse(s), 6, 16);
      }));
}
