// Adaptive hexahedral meshing (Alg. 5) of CGAL's elephant to level 8, printing the table of
// docs/benchmarks.md (a Table 1 of the paper): per level the hexahedra, the face and volume
// replacements, the hexahedra refined for the balance and the CPU time; the map stays valid.
#include <gtest/gtest.h>

#include <cstdio>

#include "model/core/validity.hpp"
#include "model/replace/pattern_folder.hpp"
#include "model/replace/tests/cgal_surface.hpp"
#include "model/replace/tests/replace_fixtures.hpp"

namespace gmr::replace {
namespace {

TEST(AdaptiveMeshingSlow, ElephantEightLevels) {
  const std::string off = testing::cgal_mesh("elephant");
  if (off.empty())
    GTEST_SKIP() << "CGAL's data meshes are not installed (libcgal-demo, tools/setup.sh)";
  const testing::CgalSurface surface(off);
  PatternStore store(Mode::Unoriented);
  for (auto& p : load_patterns(testing::patterns_dir("hex-subdivision"))) store.add(std::move(p));
  const auto [lo, size] = surface.root_cube();
  FlaggedMap m = box_hexahedron(lo, size);
  const auto levels = refine_adaptively(m, store, 8, surface.box_test());
  std::printf(
      "elephant (%zu triangles)\n| level | #volumes | #f-replacements | #v-replacements | balance "
      "| time (s) |\n",
      surface.triangles());
  size_t volumes = 1;
  for (const MeshingLevel& l : levels) {
    std::printf("| %d | %zu | %zu | %zu | %zu | %.3f |\n", l.level, l.volumes, l.face_replacements,
                l.volume_replacements, l.balanced, l.seconds);
    volumes += 7 * l.volume_replacements;
    EXPECT_EQ(l.volumes, volumes);
  }
  EXPECT_TRUE(is_valid(m.map));
  std::printf("valid, %zu darts\n", m.map.size());
}

}  // namespace
}  // namespace gmr::replace
