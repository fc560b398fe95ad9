// The library of standard operations (tools/data/rules/*.json): every file reads, is accepted by
// the scheme checker, and applies on the builders' objects with the expected cell counts and a
// valid result.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <utility>

#include "checker/check_format.hpp"
#include "checker/scheme_checker.hpp"
#include "model/core/builders.hpp"
#include "model/core/orbit.hpp"
#include "model/core/signature.hpp"
#include "model/core/validity.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "model/scheme/scheme_engine.hpp"
#include "model/testing/source_tree.hpp"

using namespace gmr;
using namespace gmr::scheme;
using namespace gmr::io;
using namespace gmr::checker;

namespace {

std::filesystem::path rules_dir() { return gmr::testing::source_path("tools/data/rules"); }

RuleScheme lib(const std::string& name) { return read_scheme_file(rules_dir() / (name + ".json")); }

struct Outcome {
  Map map{0};
  size_t darts = 0;
  std::vector<size_t> cells;
};

Outcome apply_ok(const std::string& rule, const Map& g, const std::vector<Dart>& hooks) {
  auto [h, a] = scheme::apply(SchemeEngine(lib(rule)), std::as_const(g), hooks);
  EXPECT_TRUE(a.applied) << rule << ": " << a.why;
  EXPECT_TRUE(is_valid(h)) << rule;
  return Outcome{h, h.size(), count_all_cells(h)};
}

using Cells = std::vector<size_t>;

// apply_ok, with a result of `darts` darts and `cells` i-cells (i = 0..n).
Outcome expect_outcome(const std::string& rule, const Map& g, const std::vector<Dart>& hooks,
                       size_t darts, const Cells& cells) {
  Outcome o = apply_ok(rule, g, hooks);
  EXPECT_EQ(o.darts, darts) << rule;
  EXPECT_EQ(o.cells, cells) << rule;
  return o;
}

}  // namespace

TEST(SchemeLibrary, EveryFileIsReadAndAccepted) {
  size_t count = 0;
  std::set<std::string> strict_rejects;
  for (const auto& e : std::filesystem::directory_iterator(rules_dir())) {
    if (e.path().extension() != ".json") continue;
    ++count;
    RuleScheme r = read_scheme_file(e.path());
    EXPECT_EQ(r.name, e.path().stem().string());
    CheckReport rep = check_scheme(r);
    EXPECT_TRUE(rep.ok()) << to_text(rep);
    EXPECT_EQ(rep.warnings(), 0u) << to_text(rep);
    // The literal Algorithm 3 also rejects preserved nodes whose PRESERVED 0-arc is
    // not on a (0,2)-cycle of R (their 2-link lies outside the orbit), although these operations
    // are valid (every application in the tests below yields a valid G-map).
    SchemeCheckOptions strict;
    strict.algorithm3_strict = true;
    if (!check_scheme(r, strict).ok()) strict_rejects.insert(r.name);
    EXPECT_TRUE(SchemeEngine(r).not_combinatorial().empty());
  }
  EXPECT_EQ(count, 16u);
  EXPECT_EQ(strict_rejects,
            (std::set<std::string>{"face_extrusion", "face_triangulation", "sew3", "unsew3"}));
}

TEST(SchemeLibrary, VertexInsertion) {
  const Map cube = make_cube(2);
  const Outcome a = expect_outcome("vertex_insertion", cube, {0}, 52u, Cells{9, 13, 6});
  // Folded on <2>: the same operation (isomorphic results).
  Outcome b = apply_ok("vertex_insertion_folded_2", cube, {0});
  EXPECT_EQ(b.darts, 52u);
  EXPECT_TRUE(is_isomorphic(a.map, b.map));
  // Free edge: 2 -> 4 darts; boundary edge of a grid: +2 darts.
  EXPECT_EQ(apply_ok("vertex_insertion", make_free_edge(2), {0}).darts, 4u);
  const Map grid = make_grid(2, 2);
  Dart boundary = 0;
  while (!grid.is_free(2, boundary)) ++boundary;
  Outcome c = apply_ok("vertex_insertion", grid, {boundary});
  EXPECT_EQ(c.darts, grid.size() + 2);
  EXPECT_EQ(apply_ok("vertex_insertion", make_torus(4, 3), {5}).cells, (Cells{13, 25, 12}));
}

TEST(SchemeLibrary, Triangulations) {
  const Map cube = make_cube(2);
  expect_outcome("face_triangulation", cube, {0}, 64u, Cells{9, 16, 9});
  expect_outcome("edge_triangulation", cube, {0}, 288u, Cells{26, 72, 48});
  Outcome t = apply_ok("edge_triangulation", make_tetrahedron(2), {0});
  EXPECT_EQ(t.cells, (Cells{14, 36, 24}));
}

TEST(SchemeLibrary, Subdivisions) {
  expect_outcome("quad_subdivision", make_cube(2), {0}, 192u, Cells{26, 48, 24});
  const Outcome qt =
      expect_outcome("quad_subdivision", make_torus(4, 3), {0}, 384u, Cells{48, 96, 48});
  EXPECT_EQ(euler_characteristic(qt.map), 0);
  expect_outcome("quad_subdivision", make_grid(2, 2), {0}, 128u, Cells{25, 40, 16});
  expect_outcome("loop_subdivision", make_tetrahedron(2), {0}, 96u, Cells{10, 24, 16});
  Outcome lc = apply_ok("loop_subdivision", make_cube(2), {0});
  EXPECT_EQ(lc.cells, (Cells{20, 48, 30}));
}

TEST(SchemeLibrary, ExtrusionAndDualVertex) {
  const Map cube = make_cube(2);
  expect_outcome("face_extrusion", cube, {0}, 80u, Cells{12, 20, 10});
  Outcome et = apply_ok("face_extrusion", make_torus(3, 3), {0});
  EXPECT_EQ(et.cells, (Cells{13, 26, 13}));
  expect_outcome("dual_vertex_insertion", cube, {0}, 52u, Cells{8, 13, 7});
}

TEST(SchemeLibrary, SewAndUnsew2) {
  const Map cube = make_cube(2);
  const Dart d = 0, e = cube.alpha(2, 0);
  Outcome u = apply_ok("unsew2", cube, {d});
  EXPECT_EQ(u.cells, (Cells{8, 13, 6}));
  EXPECT_TRUE(u.map.is_free(2, d) && u.map.is_free(2, e));
  Outcome s = apply_ok("sew2", u.map, {d, e});
  EXPECT_TRUE(is_isomorphic(s.map, cube));
  // Sewing non-free edges is not applicable.
  auto [h, a] = scheme::apply(SchemeEngine(lib("sew2")), std::as_const(cube), {d, e});
  EXPECT_FALSE(a.applied);
}

TEST(SchemeLibrary, SewAndUnsew3OnStackedCubes) {
  const Map g = make_stacked_cubes();
  Dart d = 0;
  while (g.is_free(3, d)) ++d;
  const Dart e = g.alpha(3, d);
  Outcome u = apply_ok("unsew3", g, {d});
  EXPECT_EQ(count_components(u.map), 2u);
  EXPECT_EQ(free_darts(u.map, 3).size(), 96u);
  Outcome s = apply_ok("sew3", u.map, {d, e});
  EXPECT_TRUE(is_isomorphic(s.map, g));
  EXPECT_EQ(count_components(s.map), 1u);
}

TEST(SchemeLibrary, EdgeDeletionAndCollapse) {
  const Map cube = make_cube(2);
  expect_outcome("edge_deletion", cube, {0}, 44u, Cells{8, 11, 5});
  expect_outcome("edge_collapse", cube, {0}, 44u, Cells{7, 11, 6});
  Outcome t = apply_ok("edge_collapse", make_torus(3, 3), {0});
  EXPECT_EQ(t.cells, (Cells{8, 17, 9}));
}
