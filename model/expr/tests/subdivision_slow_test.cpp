// Oracle on CGAL's own closed data meshes (Debian's libcgal-demo ships them in data.tar.gz; the
// test unpacks the ones it uses into the build directory, nothing is committed): the four
// subdivision rule schemes with their position expressions give CGAL::Subdivision_method_3's
// meshes (isomorphic, positions within 1e-9 relative), 1 and 3 iterations. sqrt(3) triples the
// face count of bunny00 (75408 -> 226224 faces).
#include <cstdlib>
#include <filesystem>

#include "model/expr/tests/subdivision_oracle.hpp"
#include "model/testing/cgal_data.hpp"

using namespace gmr::expr::oracle;
namespace fs = std::filesystem;

namespace {

using gmr::testing::cgal_mesh;

#define REQUIRE_MESH(var, name)                                                         \
  const std::string var = cgal_mesh(name);                                              \
  if (var.empty())                                                                      \
  GTEST_SKIP() << "CGAL's data meshes are not installed: Debian package libcgal-demo (" \
               << gmr::testing::kCgalDataArchive << "), installed by tools/setup.sh"

}  // namespace

TEST(SubdivisionOracleSlow, Elephant) {
  REQUIRE_MESH(off, "elephant");
  for (Method m : {Method::CatmullClark, Method::Loop, Method::Sqrt3, Method::DooSabin})
    for (int it : {1, 3}) check(off, m, it);
}

TEST(SubdivisionOracleSlow, Cow) {
  REQUIRE_MESH(off, "cow");
  for (Method m : {Method::CatmullClark, Method::Loop, Method::Sqrt3, Method::DooSabin})
    for (int it : {1, 3}) check(off, m, it);
}

TEST(SubdivisionOracleSlow, Sqrt3TriplesBunnyFaces) {
  REQUIRE_MESH(off, "bunny00");
  const gmr::io::FaceList ours = gmr_subdivide(off, Method::Sqrt3, 1);
  EXPECT_EQ(ours.faces.size(), 3u * 75408u);
  expect_same_mesh(ours, cgal_subdivide(off, Method::Sqrt3, 1), "bunny00, sqrt3, 1 iteration");
}
