// Property (thesis Thm. 8/13 with the overlap condition checked at application time): when the
// static checks accept a scheme (no error, no E-merge-instances warning) and an application at a
// dart gives a valid G-map without E-overlap, the result is embedding-consistent: every orbit of
// every embedding holds exactly one value (Embedding::check), and the propagation reports nothing.
// Random schemes (model/testing/random_schemes.hpp) with random position and colour expressions,
// on random glued polygons with random positions (on <1,2>) and face colours (on <0,1>); 400
// seeds, the seed printed on failure.
#include <gtest/gtest.h>

#include "checker/scheme_checker.hpp"
#include "model/core/orbit.hpp"
#include "model/core/validity.hpp"
#include "model/expr/compiled_scheme.hpp"
#include "model/expr/propagation.hpp"
#include "model/testing/random_maps.hpp"
#include "model/testing/random_schemes.hpp"

using namespace gmr;
using namespace gmr::testing;

namespace {

double unit(Rng& rng) { return static_cast<double>(uniform(rng, 0, 1000)) / 1000.0; }

EmbeddedMap random_embedded_map(Rng& rng) {
  GluedPolygonsOptions opt;
  opt.min_sides = 2;
  opt.max_faces = 6;
  EmbeddedMap m;
  m.map = random_glued_polygons(rng, opt);
  EmbeddingField pos = EmbeddingField::numeric("position", OrbitType{1, 2});
  for (Dart r : orbit_representatives(m.map, OrbitType{1, 2}))
    pos.values.set(m.map, r, {unit(rng), unit(rng), unit(rng)});
  EmbeddingField col = EmbeddingField::numeric("colour", OrbitType{0, 1});
  for (Dart r : orbit_representatives(m.map, OrbitType{0, 1}))
    col.values.set(m.map, r, {unit(rng), unit(rng), unit(rng)});
  m.fields.push_back(std::move(pos));
  m.fields.push_back(std::move(col));
  return m;
}

void add_random_expressions(Rng& rng, scheme::RuleScheme& s) {
  s.embeddings = {{"position", OrbitType{1, 2}, "point"}, {"colour", OrbitType{0, 1}, "colour"}};
  const std::string h = s.hooks[0];
  const std::vector<std::string> positions = {h + ".position", "middle(<0>_position(" + h + "))",
                                              h + ".position + vector(0, 0, 1)",
                                              "middle(<0,1>_position(" + h + "))"};
  const std::vector<std::string> colours = {h + ".colour", "colour(0.5, 0.5, 0.5)",
                                            "clamp(2 * " + h + ".colour)"};
  for (auto& n : s.right.nodes) {
    if (chance(rng, 50))
      n.expressions.push_back(
          {"position", positions[uniform(rng, 0, positions.size() - 1)], {}, {}});
    if (chance(rng, 50))
      n.expressions.push_back({"colour", colours[uniform(rng, 0, colours.size() - 1)], {}, {}});
  }
}

}  // namespace

TEST(EmbeddingConsistency, AcceptedSchemesGiveConsistentResults) {
  size_t accepted = 0, applied = 0, overlaps = 0;
  for (uint64_t seed = 1; seed <= 400; ++seed) {
    Rng rng(seed);
    scheme::RuleScheme s = random_scheme(rng);
    add_random_expressions(rng, s);
    const checker::CheckReport rep = checker::check_scheme(s);
    if (!rep.ok() || rep.count("E-merge-instances") > 0) continue;
    ++accepted;
    const scheme::SchemeEngine engine(s);
    const expr::CompiledScheme cs = expr::compile_scheme(s);
    EmbeddedMap m = random_embedded_map(rng);
    const Dart hook = static_cast<Dart>(uniform(rng, 0, m.map.size() - 1));
    expr::EmbeddingPropagation p(cs, m);
    if (!scheme::apply(engine, m.map, {hook}, &p)) continue;
    if (!check_validity(m.map).ok()) continue;
    bool overlap = false;
    for (const auto& i : p.issues()) overlap |= i.code == "E-overlap";
    if (overlap) {
      ++overlaps;
      continue;
    }
    ++applied;
    EXPECT_EQ(p.issue_count(), 0u)
        << "seed " << seed << ": " << p.issues()[0].code << " " << p.issues()[0].message;
    for (const auto& f : m.fields) {
      const auto issues = f.values.check(m.map);
      EXPECT_TRUE(issues.empty()) << "seed " << seed << ", embedding " << f.name() << ": "
                                  << issues[0].problem;
    }
  }
  std::cout << "[ property ] " << accepted << " schemes accepted, " << applied
            << " consistent applications checked, " << overlaps << " overlaps (dynamic)\n";
  EXPECT_GT(applied, 20u);
}
