// The defining property on the library schemes and on the 50 Jerboa fixture rules: engine ==
// instantiation + DPO (same map up to the isomorphism given by the comatches), including the
// cases where neither applies.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "model/core/builders.hpp"
#include "model/core/error.hpp"
#include "model/core/validity.hpp"
#include "model/rule_io/jme_import.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "model/scheme/tests/scheme_dpo_compare.hpp"
#include "model/testing/source_tree.hpp"

using namespace gmr;
using namespace gmr::scheme;
using namespace gmr::io;
using namespace gmr::testing;

namespace {
std::string root() { return gmr::testing::source_path("."); }

// Runs the comparison at up to `samples` hook choices; returns (applied, refused) counts.
std::pair<size_t, size_t> sweep(const Map& g, const RuleScheme& s, size_t samples) {
  size_t applied = 0, refused = 0;
  const auto darts = g.darts();
  const size_t hooks = s.hooks.size();
  for (size_t k = 0; k < samples; ++k) {
    std::vector<Dart> hd;
    for (size_t c = 0; c < hooks; ++c) hd.push_back(darts[(k * 7 + c * 13 + c * k) % darts.size()]);
    if (hooks == 0 && k > 0) break;
    EngineVsDpo r = compare_engine_dpo(g, s, hd);
    EXPECT_TRUE(r.problem.empty())
        << s.name << " at dart " << (hd.empty() ? 0 : hd[0]) << ": " << r.problem;
    (r.engine_applied ? applied : refused)++;
  }
  return {applied, refused};
}
}  // namespace

TEST(EngineVsDpo, LibrarySchemes) {
  size_t applied = 0;
  for (const auto& e : std::filesystem::directory_iterator(root() + "/tools/data/rules")) {
    const RuleScheme s = read_scheme_file(e.path());
    std::vector<Map> objects;
    if (s.dimension == 2) {
      objects.push_back(make_cube(2));
      objects.push_back(make_grid(2, 2));
      objects.push_back(make_torus(3, 3));
    } else {
      objects.push_back(make_stacked_cubes());
      objects.push_back(make_cube(3));
    }
    for (const Map& g : objects) applied += sweep(g, s, 12).first;
  }
  EXPECT_GT(applied, 100u);
}

TEST(EngineVsDpo, JerboaFixtureRules) {
  JmeModeler m = read_jme_file(root() + "/tools/data/jerboa/JerboaTrackingOrbit.jme");
  size_t applied = 0, compared = 0;
  for (const RuleScheme& s : m.rules) {
    std::unique_ptr<SchemeEngine> e;
    try {
      e = std::make_unique<SchemeEngine>(s);
    } catch (const Error&) {
      continue;  // malformed for the engine (reported by the checker)
    }
    if (!e->not_combinatorial().empty()) continue;
    ++compared;
    for (const Map& g : {make_stacked_cubes(), make_cube(3),
                         make_polycube({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}})})
      applied += sweep(g, s, 10).first;
  }
  EXPECT_GE(compared, 40u);
  EXPECT_GT(applied, 50u);
}
