// Pattern files and their validation at load; the pattern store.
#include <gtest/gtest.h>

#include <fstream>

#include "model/core/builders.hpp"
#include "model/map_io/map_json.hpp"
#include "model/replace/pattern_store.hpp"
#include "model/replace/tests/replace_fixtures.hpp"
#include "model/testing/scratch_dir.hpp"

namespace gmr::replace {
namespace {

namespace fs = std::filesystem;

struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name)
      : path(gmr::testing::scratch_path("gmr_replace_" + name)) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  void write(const std::string& file, const Map& g) {
    io::write_map_json_file(path / file, EmbeddedMap(g));
  }
};

TEST(PatternFolder, LoadsTheConformalFaceSetInNameOrder) {
  const auto ps = load_patterns(testing::patterns_dir("conformal-faces"));
  ASSERT_EQ(ps.size(), 5u);
  EXPECT_EQ(ps.front().name, "split1");
  EXPECT_EQ(ps.back().name, "split4");
  for (const Pattern& p : ps) {
    EXPECT_EQ(p.cell_dim, 2);
    EXPECT_GT(p.interior, 0u);
    EXPECT_FALSE(p.positive.empty());
    // 4 corners with 2 flagged darts each on the boundary, never an inner dart.
    size_t boundary_flags = 0, inner_flags = 0;
    p.map.map.for_each_dart([&](Dart d) {
      (p.map.map.is_free(2, d) ? boundary_flags : inner_flags) += p.map.flag[d] != 0;
    });
    EXPECT_EQ(boundary_flags, 8u) << p.name;
    EXPECT_EQ(inner_flags, 0u) << p.name;
  }
  // No two patterns of the set share a boundary, in either mode.
  for (Mode mode : {Mode::Unoriented, Mode::Oriented}) {
    PatternStore s(mode);
    for (const Pattern& p : ps) s.add(p);
    EXPECT_TRUE(s.duplicates().empty());
    EXPECT_EQ(s.keys(), 5u);
  }
}

TEST(PatternFolder, RejectsNonPatternsByName) {
  TempDir d("reject");
  auto expect_reject = [&](const std::string& file, const Map& g, const std::string& why) {
    d.write(file, g);
    try {
      load_pattern(d.path / file);
      ADD_FAILURE() << file << " accepted";
    } catch (const Error& e) {
      EXPECT_NE(e.location().find(file), std::string::npos)
          << file << ": " << e.location() << ": " << e.message();
      EXPECT_NE(e.message().find(why), std::string::npos) << e.message();
    }
  };
  expect_reject("closed.json", make_cube(2), "no boundary");
  expect_reject("open.json", make_free_edge(2), "1-free");
  expect_reject("dim1.json", make_polygon(3, 1), "dimension 1");
  Map two = make_polygon(4);
  const Map tri = make_polygon(3);
  const Dart base = two.add_darts(tri.size());
  tri.for_each_dart([&](Dart x) {
    for (int i = 0; i <= 2; ++i) two.set_alpha(i, base + x, base + tri.alpha(i, x));
  });
  expect_reject("two.json", two, "not connected");
  // The sides of a square prism form an annulus: two boundary cycles.
  expect_reject("annulus.json",
                surface_from_faces({{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}, 8),
                "not one cycle");
  EXPECT_THROW(load_patterns(d.path / "missing"), Error);
  TempDir empty("empty");
  EXPECT_THROW(load_patterns(empty.path), Error);
}

// The paper's Fig. 4 phenomenon: a boundary automorphism that does not extend to the interior. The
// two-adjacent-split pattern has a mirror symmetry of its boundary (through the corner between the
// split edges) that its interior (a triangle on one side only) does not share.
TEST(PatternStore, AmbiguousPatternsAreThoseWithNonExtendingBoundaryAutomorphisms) {
  for (Mode mode : {Mode::Unoriented, Mode::Oriented}) {
    PatternStore s(mode);
    for (auto& p : load_patterns(testing::patterns_dir("conformal-faces"))) s.add(std::move(p));
    s.add(testing::pattern_file("hex-subdivision", "hex8"));
    s.add(testing::pattern_file("tet-to-hex", "tet4"));
    for (size_t i = 0; i < s.patterns().size(); ++i) {
      const bool expected = mode == Mode::Unoriented && s.patterns()[i].name == "split2-adjacent";
      EXPECT_EQ(s.entry(i).ambiguous, expected) << s.patterns()[i].name << " " << to_string(mode);
      if (s.patterns()[i].name == "split2-adjacent") {
        EXPECT_EQ(s.entry(i).automorphisms, mode == Mode::Unoriented ? 2u : 1u);
      }
    }
  }
}

TEST(PatternStore, KeysHoldSeveralPatternsAndSeparateCellDimensions) {
  PatternStore s(Mode::Unoriented);
  s.add(testing::pattern_file("conformal-faces", "split4"));
  s.add(testing::pattern_file("conformal-faces", "split4"));
  s.add(testing::pattern_file("tet-to-hex", "triangle3"));
  ASSERT_EQ(s.duplicates().size(), 1u);
  EXPECT_EQ(s.duplicates()[0], (std::vector<size_t>{0, 1}));
  EXPECT_EQ(s.keys(), 2u);
  EXPECT_EQ(s.entry(0).automorphisms, 8u);  // the flagged square boundary: its dihedral group
  EXPECT_EQ(s.entry(2).automorphisms, 6u);
  PatternStore o(Mode::Oriented);
  o.add(testing::pattern_file("conformal-faces", "split4"));
  EXPECT_EQ(o.entry(0).automorphisms, 4u);
}

}  // namespace
}  // namespace gmr::replace
