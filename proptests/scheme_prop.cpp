// Properties of rule schemes (issue 4), on random valid G-maps (model/random_maps.hpp through
// MapCase) and random hook darts, over a pool of schemes: the library (tools/data/rules) and the
// 50 rules of the Jerboa fixture.
//  * defining property: the engine's result equals instantiation + DPO (with corresponding
//    comatch), and both refuse the same applications;
//  * soundness of the checker: if check_scheme accepts a scheme, every application yields a valid
//    G-map.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <memory>

#include "checker/scheme_checker.hpp"
#include "model/error.hpp"
#include "model/jme_import.hpp"
#include "model/scheme_json.hpp"
#include "model/tests/scheme_dpo_compare.hpp"
#include "model/validity.hpp"
#include "proptests/harness.hpp"

using namespace gmr;
using namespace gmr::prop;

namespace {

struct PoolEntry {
  RuleScheme scheme;
  bool accepted;
};

const std::vector<PoolEntry>& pool() {
  static const std::vector<PoolEntry> p = [] {
    std::vector<PoolEntry> out;
    const char* r = std::getenv("GMR_SOURCE_DIR");
    const std::string root = r ? r : ".";
    std::vector<RuleScheme> all;
    for (const auto& e : std::filesystem::directory_iterator(root + "/tools/data/rules"))
      all.push_back(read_scheme_file(e.path()));
    for (auto& s : read_jme_file(root + "/model/tests/data/JerboaTrackingOrbit.jme").rules) all.push_back(s);
    for (auto& s : all) {
      try {
        SchemeEngine e(s);
        if (!e.not_combinatorial().empty()) continue;
      } catch (const Error&) {
        continue;
      }
      out.push_back({s, check_scheme(s).ok()});
    }
    return out;
  }();
  return p;
}

void property(const MapCase& c) {
    const GMap g = c.build();
    std::vector<size_t> fit;
    for (size_t k = 0; k < pool().size(); ++k)
      if (pool()[k].scheme.dimension == g.dimension()) fit.push_back(k);
    RC_PRE(!fit.empty());
    const PoolEntry& pe = pool()[fit[*rc::gen::inRange<size_t>(0, fit.size())]];
    const auto darts = g.darts();
    std::vector<Dart> hooks;
    for (size_t h = 0; h < pe.scheme.hooks.size(); ++h) hooks.push_back(darts[*rc::gen::inRange<size_t>(0, darts.size())]);
    const ::gmr::testing::EngineVsDpo r = ::gmr::testing::compare_engine_dpo(g, pe.scheme, hooks);
    RC_LOG() << "scheme " << pe.scheme.name << (r.engine_applied ? " applied" : " refused") << "\n";
    RC_TAG(r.engine_applied ? "applied" : "refused");
    RC_ASSERT(r.problem.empty());
    if (r.engine_applied && pe.accepted) RC_ASSERT(check_validity(r.result).ok());
}

}  // namespace

TEST(SchemeProps, EngineEqualsDpoAndAcceptedSchemesPreserveGMaps2D) {
  ASSERT_GT(pool().size(), 40u);
  EXPECT_TRUE(check_map_property("scheme_engine_dpo_2d", gen_map_case_of_dim(2, 5), property));
}

TEST(SchemeProps, EngineEqualsDpoAndAcceptedSchemesPreserveGMaps3D) {
  EXPECT_TRUE(check_map_property("scheme_engine_dpo_3d", gen_map_case_of_dim(3, 3), property));
}
