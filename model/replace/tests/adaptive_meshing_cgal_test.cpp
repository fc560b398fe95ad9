// Adaptive hexahedral meshing (Alg. 5) of CGAL's elephant, the hexahedra meeting the surface found
// with CGAL's AABB tree: five levels (the slow test goes to eight).
#include <gtest/gtest.h>

#include "model/core/validity.hpp"
#include "model/replace/pattern_folder.hpp"
#include "model/replace/tests/cgal_surface.hpp"
#include "model/replace/tests/replace_fixtures.hpp"

namespace gmr::replace {
namespace {

TEST(AdaptiveMeshingCgal, ElephantFiveLevels) {
  const std::string off = testing::cgal_mesh("elephant");
  if (off.empty())
    GTEST_SKIP() << "CGAL's data meshes are not installed (libcgal-demo, tools/setup.sh)";
  const testing::CgalSurface surface(off);
  ASSERT_TRUE(surface.closed());
  PatternStore store(Mode::Unoriented);
  for (auto& p : load_patterns(testing::patterns_dir("hex-subdivision"))) store.add(std::move(p));
  const auto [lo, size] = surface.root_cube();
  FlaggedMap m = box_hexahedron(lo, size);
  const auto levels = refine_adaptively(m, store, 5, surface.box_test());
  size_t volumes = 1;
  for (const MeshingLevel& l : levels) {
    EXPECT_GT(l.volume_replacements, 0u);
    volumes += 7 * l.volume_replacements;
    EXPECT_EQ(l.volumes, volumes);
  }
  EXPECT_TRUE(is_valid(m.map));
}

}  // namespace
}  // namespace gmr::replace
