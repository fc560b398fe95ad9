// Embeddings through the whole-component path (propagation.hpp, "Whole components") against the
// general path (one scheme::apply per visited dart with EmbeddingPropagation as observer):
// the same map dart for dart, the same value on every dart of every embedding, the same issues.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "model/core/orbit.hpp"
#include "model/expr/compiled_scheme.hpp"
#include "model/expr/propagation.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "model/testing/random_maps.hpp"
#include "model/testing/random_schemes.hpp"

using namespace gmr;
using namespace gmr::expr;
namespace gt = gmr::testing;

namespace {

std::string rules_dir() {
  const char* s = std::getenv("GMR_SOURCE_DIR");
  return std::string(s ? s : ".") + "/tools/data/rules/";
}

// Random values on every orbit of a field (some orbits left without value when `holes`).
EmbeddingField random_field(gt::Rng& rng, const Map& g, const std::string& name, const OrbitType& o,
                            bool holes) {
  EmbeddingField f = EmbeddingField::numeric(name, o);
  for (Dart rep : orbit_representatives(g, o)) {
    if (holes && gt::chance(rng, 10)) continue;
    Vec3 x;
    for (double& c : x) c = static_cast<double>(gt::uniform(rng, 0, 1 << 20)) / 4096.0 - 128.0;
    f.values.set(g, rep, x);
  }
  return f;
}

// Positions on <1,2>, and two embeddings no subdivision scheme declares (face colours on <0,1>,
// edge marks on <0,2>), inherited by step 3.
EmbeddedMap random_embedded(gt::Rng& rng, const Map& g, bool holes) {
  EmbeddedMap m;
  m.map = g;
  m.fields.push_back(random_field(rng, g, "position", OrbitType{1, 2}, false));
  m.fields.push_back(random_field(rng, g, "colour", OrbitType{0, 1}, holes));
  m.fields.push_back(random_field(rng, g, "mark", OrbitType{0, 2}, holes));
  return m;
}

struct Outcome {
  std::vector<std::string> issue_codes;  // sorted
  size_t issues = 0;
  bool threw = false;
};

Outcome run(const scheme::SchemeEngine& engine, const CompiledScheme& cs, EmbeddedMap& m,
            bool by_components) {
  Outcome out;
  EmbeddingPropagation p(cs, m);
  try {
    scheme::apply_everywhere(engine, m.map,
                             {.keep_tables = false,
                              .observer = &p,
                              .path = by_components ? scheme::EverywherePath::ByComponents
                                                    : scheme::EverywherePath::AtEachDart});
  } catch (const Error&) {
    out.threw = true;
  }
  for (const auto& i : p.issues()) out.issue_codes.push_back(i.code + " " + i.embedding);
  std::sort(out.issue_codes.begin(), out.issue_codes.end());
  out.issues = p.issue_count();
  return out;
}

bool close(double a, double b) {
  return std::fabs(a - b) <= 1e-12 * std::max({1.0, std::fabs(a), std::fabs(b)});
}

void expect_same(const EmbeddedMap& a, const EmbeddedMap& b, const std::string& where) {
  ASSERT_EQ(a.map.capacity(), b.map.capacity()) << where;
  for (Dart d = 0; d < a.map.capacity(); ++d) {
    ASSERT_EQ(a.map.alive(d), b.map.alive(d)) << where;
    if (!a.map.alive(d)) continue;
    for (int i = 0; i <= a.map.dimension(); ++i)
      ASSERT_EQ(a.map.alpha(i, d), b.map.alpha(i, d)) << where;
    for (size_t f = 0; f < a.fields.size(); ++f) {
      const auto& x = a.fields[f].values;
      const auto& y = b.fields[f].values;
      ASSERT_EQ(x.has(d), y.has(d)) << where << ", " << x.name() << ", dart " << d;
      if (!x.has(d)) continue;
      for (size_t k = 0; k < 3; ++k)
        ASSERT_TRUE(close(x.get(d)[k], y.get(d)[k]))
            << where << ", " << x.name() << ", dart " << d << ": " << x.get(d)[k] << " vs "
            << y.get(d)[k];
    }
  }
}

size_t compare(const scheme::RuleScheme& s, const EmbeddedMap& m0, int iterations,
               const std::string& where) {
  const scheme::SchemeEngine engine(s);
  const CompiledScheme cs = compile_scheme(s);
  EmbeddedMap a = m0, b = m0;
  size_t issues = 0;
  for (int k = 0; k < iterations; ++k) {
    EXPECT_TRUE(scheme::rewrites_whole_components(engine, a.map)) << where;
    const Outcome x = run(engine, cs, a, true);
    const Outcome y = run(engine, cs, b, false);
    EXPECT_EQ(x.threw, y.threw) << where;
    EXPECT_EQ(x.issues, y.issues) << where;
    EXPECT_EQ(x.issue_codes, y.issue_codes) << where;
    expect_same(a, b, where + ", iteration " + std::to_string(k + 1));
    issues += y.issues;
    if (x.threw || y.threw) break;
  }
  return issues;
}

TEST(ComponentPropagation, SubdivisionSchemesOnRandomSurfacesGiveTheGeneralPathsValues) {
  for (const char* file : {"quad_subdivision.json", "loop_subdivision.json",
                           "sqrt3_subdivision.json", "doo_sabin_subdivision.json"}) {
    const scheme::RuleScheme s = io::read_scheme_file(rules_dir() + file);
    for (uint64_t seed = 0; seed < 12; ++seed) {
      gt::Rng rng(seed);
      gt::GluedPolygonsOptions opt;
      opt.min_sides = 3;
      opt.connected = seed % 3 != 0;
      opt.max_extra_sews = 12;
      const Map g = gt::random_glued_polygons(rng, opt);
      compare(s, random_embedded(rng, g, seed % 2 == 0), 2,
              std::string(file) + ", seed " + std::to_string(seed));
    }
  }
}

TEST(ComponentPropagation, RandomCopiesSchemesInheritAndReportAsTheGeneralPath) {
  // No expression: every value is inherited (step 3); a deleted hook leaves new orbits without
  // value (E-no-value), copies of one dart merge nothing.
  size_t issues = 0;
  for (uint64_t seed = 0; seed < 60; ++seed) {
    gt::Rng rng(7000 + seed);
    scheme::RuleScheme s = gt::random_copies_scheme(rng, 2, 4);
    gt::SewSequenceOptions opt;
    opt.n = 2;
    const Map g = gt::random_sewn_cells(rng, opt);
    issues += compare(s, random_embedded(rng, g, seed % 2 == 0), 2, "seed " + std::to_string(seed));
  }
  EXPECT_GT(issues, 0u);  // the issue paths were exercised
}

TEST(ComponentPropagation, RandomSchemesOfTheWholeComponentFormInheritAsTheGeneralPath) {
  // Explicit arcs, `_` in R labels, added and deleted nodes: classes joining several R nodes.
  size_t compared = 0;
  for (uint64_t seed = 0; seed < 4000 && compared < 40; ++seed) {
    gt::Rng rng(9000 + seed);
    gt::RandomSchemeOptions so;
    so.second_left_percent = 0;
    const scheme::RuleScheme s = gt::random_scheme(rng, so);
    gt::SewSequenceOptions mo;
    const Map g = gt::random_sewn_cells(rng, mo);
    if (!scheme::rewrites_whole_components(scheme::SchemeEngine(s), g)) continue;
    ++compared;
    compare(s, random_embedded(rng, g, seed % 2 == 0), 2, "seed " + std::to_string(seed));
  }
  EXPECT_GE(compared, 10u);
}

}  // namespace
