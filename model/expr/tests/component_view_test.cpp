// The view of a component (component_view.hpp) against the component on the map: the same links
// and slots up to the numbering by orbit dart (O's own map read in place for a whole-map component,
// a copy otherwise), the same values bit for bit for the expressions of
// the four subdivision schemes at every orbit dart (tree and program, memo mode), and an
// evaluation error of an application located on the map, not on the view.
#include "model/expr/component_view.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <regex>

#include "model/core/orbit.hpp"
#include "model/expr/compiled_scheme.hpp"
#include "model/expr/evaluator.hpp"
#include "model/expr/propagation.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "model/testing/random_maps.hpp"

using namespace gmr;
using namespace gmr::expr;
namespace gt = gmr::testing;

// Named (the test files of a module are compiled together): no clash with the others' helpers.
namespace component_view_test {

const char* const kSchemes[] = {"quad_subdivision.json", "loop_subdivision.json",
                                "sqrt3_subdivision.json", "doo_sabin_subdivision.json"};

std::string rules_dir() {
  const char* s = std::getenv("GMR_SOURCE_DIR");
  return std::string(s ? s : ".") + "/tools/data/rules/";
}

// Coordinates with every bit of the mantissa used (thirds), so that sums in different orders
// round differently.
EmbeddedMap random_positions(gt::Rng& rng, const Map& g) {
  EmbeddedMap m;
  m.map = g;
  EmbeddingField f = EmbeddingField::numeric("position", OrbitType{1, 2});
  for (Dart rep : orbit_representatives(g, OrbitType{1, 2})) {
    Vec3 x;
    for (double& c : x) c = static_cast<double>(gt::uniform(rng, 0, 1 << 20)) / 3.0 - 100000.0;
    f.values.set(g, rep, x);
  }
  m.fields.push_back(std::move(f));
  return m;
}

Map random_surface(uint64_t seed) {
  gt::Rng rng(seed);
  gt::GluedPolygonsOptions opt;
  opt.min_sides = 3;
  opt.connected = seed % 3 != 0;
  opt.max_extra_sews = 12;
  return gt::random_glued_polygons(rng, opt);
}

// Before each component's rewrite: the view built and compared with the component on the map.
// Applied by components only: it fails when it sees an application at one dart.
class ViewChecker : public scheme::ApplicationObserver, public scheme::ComponentObserver {
 public:
  ViewChecker(const CompiledScheme& cs, const EmbeddedMap& m) : cs_(cs), m_(m) {}
  size_t components = 0, evaluations = 0, read_in_place = 0;

  void before_rewrite(const Map&, const scheme::SchemeApplication&,
                      const scheme::OrbitGraph&) override {
    ADD_FAILURE() << "applied at one dart";
  }
  void after_rewrite(const Map&, const scheme::SchemeApplication&,
                     const scheme::OrbitGraph&) override {}

  void before_rewrite(const Map& g, const scheme::ComponentInstance& c) override {
    const scheme::RuleScheme& s = *cs_.scheme;
    std::vector<const EmbeddingField*> fields{&m_.fields[0]};
    ComponentView v;
    view_component(g, c, s.left.nodes[s.hook_nodes()[0]].label, fields, v);
    ASSERT_EQ(v.map().capacity(), c.size());
    ASSERT_NE(c.orbit_map, nullptr);
    ASSERT_EQ(&v.map() == c.orbit_map, c.whole_map);
    read_in_place += c.whole_map;
    const Embedding<Vec3>& on_map = m_.fields[0].values;
    const Embedding<Vec3>& on_view = v.fields[0]->values;
    for (uint32_t b = 0; b < c.size(); ++b) {
      for (int i = 0; i <= g.dimension(); ++i)
        ASSERT_EQ(c.darts[v.map().alpha(i, b)], g.alpha(i, c.darts[b]));
      ASSERT_EQ(on_view.slot(b), on_map.slot(c.darts[b]));
    }
    ASSERT_EQ(on_view.num_values(), on_map.num_values());
    for (uint32_t x = 0; x < on_map.num_values(); ++x) ASSERT_EQ(on_view.value(x), on_map.value(x));

    Evaluator map_ev(g, cs_.embeddings, fields), view_ev(v.map(), cs_.embeddings, {&*v.fields[0]});
    map_ev.memoise_collects(true);
    view_ev.memoise_collects(true);
    const std::string where = "test";
    for (size_t e = 0; e < cs_.right.size(); ++e)
      for (const auto& x : cs_.right[e]) {
        if (!x) continue;
        const std::optional<Program> p = compile_program(*x);
        ASSERT_TRUE(p.has_value());
        for (uint32_t b = 0; b < c.size(); ++b) {
          const Dart d = c.darts[b];
          for (int tree = 0; tree < 2; ++tree) {
            const Val a = tree ? map_ev.evaluate(*x, &d, cs_.embeddings[e].type, where)
                               : map_ev.evaluate(*p, &d, cs_.embeddings[e].type, where);
            const Val w = tree ? view_ev.evaluate(*x, &b, cs_.embeddings[e].type, where)
                               : view_ev.evaluate(*p, &b, cs_.embeddings[e].type, where);
            ASSERT_EQ(std::memcmp(&a, &w, sizeof(Val)), 0) << "orbit dart " << b << ", dart " << d;
            ++evaluations;
          }
        }
      }
    ++components;
  }
  void after_rewrite(const Map&, const scheme::ComponentInstance&) override {}

 private:
  const CompiledScheme& cs_;
  const EmbeddedMap& m_;
};

}  // namespace component_view_test

TEST(ComponentView, LinksSlotsAndValuesAreTheComponentsNumberedByOrbitDart) {
  using namespace component_view_test;
  for (const char* file : kSchemes) {
    const scheme::RuleScheme s = io::read_scheme_file(component_view_test::rules_dir() + file);
    const scheme::SchemeEngine engine(s);
    const CompiledScheme cs = compile_scheme(s);
    size_t whole = 0, parts = 0;
    for (uint64_t seed = 0; seed < 8; ++seed) {
      gt::Rng rng(100 + seed);
      EmbeddedMap m = random_positions(rng, random_surface(seed));
      ASSERT_TRUE(scheme::rewrites_whole_components(engine, m.map));
      ViewChecker check(cs, m);
      scheme::apply_everywhere(
          engine, m.map,
          {.keep_tables = false, .observer = &check, .path = scheme::EverywherePath::ByComponents});
      EXPECT_GT(check.components, 0u) << file << ", seed " << seed;
      EXPECT_GT(check.evaluations, 0u) << file << ", seed " << seed;
      whole += check.read_in_place;
      parts += check.components - check.read_in_place;
    }
    EXPECT_GT(whole, 0u) << file;  // both ways of making the view were compared
    EXPECT_GT(parts, 0u) << file;
  }
}

TEST(ComponentView, AnEvaluationErrorNamesADartOfTheMap) {
  using namespace component_view_test;
  // A vertex without position: the application fails, and the dart the error names is one of the
  // map's darts without a position (the view numbers darts otherwise).
  const scheme::RuleScheme s =
      io::read_scheme_file(component_view_test::rules_dir() + "loop_subdivision.json");
  const scheme::SchemeEngine engine(s);
  const CompiledScheme cs = compile_scheme(s);
  size_t checked = 0;
  for (uint64_t seed = 0; seed < 12; ++seed) {
    gt::Rng rng(300 + seed);
    const Map g = random_surface(seed * 3 + 1);  // connected: one component, evaluated on its view
    EmbeddedMap m = random_positions(rng, g);
    const auto vertices = orbit_representatives(g, OrbitType{1, 2});
    const Dart hole =
        vertices[static_cast<size_t>(gt::uniform(rng, 0, static_cast<int>(vertices.size()) - 1))];
    for (Dart x : orbit(g, OrbitType{1, 2}, hole))
      m.fields[0].values.set_slot(g, x, Embedding<Vec3>::kNoValue);
    const EmbeddedMap before = m;
    EmbeddingPropagation p(cs, m);
    try {
      scheme::apply_everywhere(engine, m.map, {.keep_tables = false, .observer = &p});
      ADD_FAILURE() << "seed " << seed << ": no error for a vertex without position";
    } catch (const Error& e) {
      std::smatch match;
      const std::string what = e.what();
      ASSERT_TRUE(std::regex_search(what, match, std::regex("dart ([0-9]+)"))) << what;
      const auto d = static_cast<Dart>(std::stoul(match[1]));
      EXPECT_TRUE(before.map.alive(d)) << what;
      EXPECT_FALSE(before.fields[0].values.has(d)) << "seed " << seed << ": " << what;
      // The values evaluated before the failing class are dropped with it: nothing was rewritten.
      EXPECT_EQ(m.fields[0].values.num_values(), before.fields[0].values.num_values())
          << "seed " << seed;
      EXPECT_EQ(m.map.size(), before.map.size()) << "seed " << seed;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 12u);
}

TEST(ComponentView, ValuesAreTheGeneralPathsBitForBitWhenNothingIsFused) {
  // Loop's topology with masks that are not fused (barycentres of sets and of arguments): the
  // whole-component path (view, shared orbit numbers and lists, program) and the general path
  // (one application per dart, the tree on the map) sum the same members in the same order, so
  // every value is the same to the bit. An orbit listed in another order than the walk's changes
  // the last bits of some barycentre.
  using namespace component_view_test;
  scheme::RuleScheme s =
      io::read_scheme_file(component_view_test::rules_dir() + "loop_subdivision.json");
  s.right.nodes[0].expressions[0].code =
      "middle(middle([e@0.position | e in <1,2>/<0,2>(n0)]), n0.position)";
  s.right.nodes[1].expressions[0].code = "middle(n0.position, n0@0.position, n0@1@0.position)";
  const scheme::SchemeEngine engine(s);
  const CompiledScheme cs = compile_scheme(s);
  size_t compared = 0;
  for (uint64_t seed = 0; seed < 10; ++seed) {
    gt::Rng rng(500 + seed);
    EmbeddedMap a = random_positions(rng, random_surface(seed));
    EmbeddedMap b = a;
    for (int iteration = 0; iteration < 2; ++iteration) {
      EmbeddingPropagation pa(cs, a), pb(cs, b);
      scheme::apply_everywhere(
          engine, a.map,
          {.keep_tables = false, .observer = &pa, .path = scheme::EverywherePath::ByComponents});
      scheme::apply_everywhere(
          engine, b.map,
          {.keep_tables = false, .observer = &pb, .path = scheme::EverywherePath::AtEachDart});
      ASSERT_EQ(a.map.capacity(), b.map.capacity());
      for (Dart d = 0; d < a.map.capacity(); ++d) {
        if (!a.map.alive(d)) continue;
        const Vec3 &x = a.fields[0].values.get(d), &y = b.fields[0].values.get(d);
        ASSERT_EQ(std::memcmp(&x, &y, sizeof x), 0) << "seed " << seed << ", dart " << d;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 1000u);
}

TEST(ComponentView, AFailingFieldDropsTheValuesOfEveryField) {
  using namespace component_view_test;
  // Loop's scheme with a second point embedding on vertices, "shade", copied and averaged like the
  // positions; the map's fields are position then shade, and one vertex has no shade: the
  // positions are evaluated and appended first, then the shade fails, and both fields are left as
  // they were.
  nlohmann::json doc = nlohmann::json::parse(
      std::ifstream(component_view_test::rules_dir() + "loop_subdivision.json"));
  doc["embeddings"].push_back({{"name", "shade"}, {"orbit", "<1,2>"}, {"type", "point"}});
  doc["right"]["nodes"][0]["expressions"].push_back({{"embedding", "shade"}, {"code", "n0.shade"}});
  doc["right"]["nodes"][1]["expressions"].push_back(
      {{"embedding", "shade"}, {"code", "(n0.shade + n0@0.shade) / 2"}});
  const scheme::RuleScheme s = io::scheme_from_json(doc, "loop with shade");
  const scheme::SchemeEngine engine(s);
  const CompiledScheme cs = compile_scheme(s);
  for (uint64_t seed = 0; seed < 6; ++seed) {
    gt::Rng rng(500 + seed);
    const Map g = random_surface(seed * 3 + 1);
    EmbeddedMap m = random_positions(rng, g);
    EmbeddingField shade = EmbeddingField::numeric("shade", OrbitType{1, 2});
    const auto vertices = orbit_representatives(g, OrbitType{1, 2});
    for (size_t i = 1; i < vertices.size(); ++i)
      shade.values.set(g, vertices[i], Vec3{static_cast<double>(i), 2.0, 3.0});
    m.fields.push_back(std::move(shade));
    const EmbeddedMap before = m;
    EmbeddingPropagation p(cs, m);
    EXPECT_THROW(scheme::apply_everywhere(engine, m.map, {.keep_tables = false, .observer = &p}),
                 Error)
        << "seed " << seed;
    ASSERT_GT(before.fields[0].values.num_values(), 0u);
    EXPECT_EQ(m.fields[0].values.num_values(), before.fields[0].values.num_values())
        << "seed " << seed;
    EXPECT_EQ(m.fields[1].values.num_values(), before.fields[1].values.num_values())
        << "seed " << seed;
    EXPECT_EQ(m.map.size(), before.map.size()) << "seed " << seed;
  }
}
