// Properties of rule schemes (issues 4 and 5), on random valid G-maps (proptests/generators.hpp)
// and random hook darts:
//  * defining property: the engine's result equals instantiation + DPO (with corresponding
//    comatch), and both refuse the same applications — on the library (tools/data/rules and the
//    50 Jerboa rules), on random schemes and on mutated library schemes (scheme_cases.hpp);
//  * soundness of the scheme checker: if check_scheme accepts a scheme, every application yields a
//    valid G-map.
#include <gtest/gtest.h>

#include "checker/check_format.hpp"
#include "checker/scheme_checker.hpp"
#include "model/core/error.hpp"
#include "model/core/validity.hpp"
#include "model/scheme/scheme_engine.hpp"
#include "model/scheme/tests/scheme_dpo_compare.hpp"
#include "proptests/generators.hpp"
#include "proptests/harness.hpp"
#include "proptests/library.hpp"
#include "proptests/scheme_cases.hpp"

using namespace gmr;
using namespace gmr::scheme;
using namespace gmr::checker;
using namespace gmr::prop;

namespace {

// Applies `s` at random hooks of a random map of its dimension: engine == instantiation + DPO,
// and a valid result when the checker accepts the scheme.
void engine_dpo_property(const RuleScheme& s, bool accepted, size_t max_map_size) {
  const MapCase mc = *gen_map_case_of_dim(s.dimension, max_map_size);
  const Map g = mc.build();
  RC_PRE(g.size() > 0u);
  const auto darts = g.darts();
  std::vector<Dart> hooks;
  for (size_t h = 0; h < s.hooks.size(); ++h)
    hooks.push_back(darts[*rc::gen::inRange<size_t>(0, darts.size())]);
  RC_LOG() << "map " << mc.str() << ", hooks";
  for (Dart h : hooks) RC_LOG() << " " << h;
  RC_LOG() << "\n";
  const ::gmr::testing::EngineVsDpo r = ::gmr::testing::compare_engine_dpo(g, s, hooks);
  RC_TAG(r.engine_applied ? "applied" : "refused");
  RC_ASSERT(r.problem.empty());
  if (r.engine_applied && accepted) {
    const auto rep = check_validity(r.result);
    if (!rep.ok()) RC_LOG() << describe_counterexample(g) << "\n";
    RC_ASSERT(rep.ok());
  }
}

// Usable by the engine (malformed schemes and schemes breaking I_S are never applied).
bool engine_usable(const RuleScheme& s) {
  try {
    return SchemeEngine(s).not_combinatorial().empty();
  } catch (const Error&) {
    return false;
  }
}

void scheme_case_property(const SchemeCase& c) {
  const RuleScheme s = c.build();
  const bool usable = engine_usable(s);
  RC_CLASSIFY(!usable, "not usable by the engine");
  if (!usable) return;
  const bool accepted = check_scheme(s).ok();
  RC_TAG(accepted ? "accepted" : "rejected");
  engine_dpo_property(s, accepted, c.n == 3 ? 2 : 4);
}

}  // namespace

TEST(SchemeProps, LibraryIsLoaded) {
  EXPECT_GT(scheme_library().size(), 40u);
  EXPECT_FALSE(library_of_dim(2, true).empty());
  EXPECT_FALSE(library_of_dim(3, true).empty());
}

TEST(SchemeProps, EngineEqualsDpoAndAcceptedSchemesPreserveGMaps2D) {
  EXPECT_TRUE(check_property<SchemeCase>("scheme_engine_dpo_2d", gen_scheme_case_of_dim(2),
                                         scheme_case_property));
}

TEST(SchemeProps, EngineEqualsDpoAndAcceptedSchemesPreserveGMaps3D) {
  EXPECT_TRUE(check_property<SchemeCase>("scheme_engine_dpo_3d", gen_scheme_case_of_dim(3),
                                         scheme_case_property));
}

TEST(SchemeProps, EngineEqualsDpoOnRandom1DSchemes) {
  EXPECT_TRUE(check_property<SchemeCase>("scheme_engine_dpo_1d", gen_scheme_case_of_dim(1),
                                         scheme_case_property));
}

// Schemes consistent by construction are accepted by the checker, and their applications give
// valid G-maps (with the engine == DPO property on the way).
TEST(SchemeProps, ConsistentByConstructionSchemesAreAcceptedAndPreserve) {
  EXPECT_TRUE(check_property<SchemeCase>("scheme_valid_accepted", gen_copies_scheme_case(),
                                         [](const SchemeCase& c) {
                                           const RuleScheme s = c.build();
                                           RC_ASSERT(engine_usable(s));
                                           const auto rep = check_scheme(s);
                                           if (!rep.ok()) RC_LOG() << to_text(rep) << "\n";
                                           RC_ASSERT(rep.ok());
                                           engine_dpo_property(s, true, c.n == 3 ? 2 : 4);
                                         }));
}
