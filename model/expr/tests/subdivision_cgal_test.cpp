// Oracle: the subdivision rule schemes of tools/data/rules with their position expressions give
// CGAL::Subdivision_method_3's meshes (isomorphic, positions within 1e-9 relative) on the small
// closed meshes of tools/data, after 1 and 3 iterations.
#include "model/expr/tests/subdivision_oracle.hpp"

using namespace gmr::expr::oracle;

namespace {

std::string data(const char* name) { return source_dir() + "/tools/data/" + name; }

}  // namespace

TEST(SubdivisionOracle, CatmullClarkCube) {
  for (int it : {1, 3}) check(data("cube.off"), Method::CatmullClark, it);
}

TEST(SubdivisionOracle, CatmullClarkTriangles) {
  for (int it : {1, 3}) {
    check(data("tetrahedron.off"), Method::CatmullClark, it);
    check(data("octahedron.off"), Method::CatmullClark, it);
  }
}

TEST(SubdivisionOracle, LoopTetrahedronAndOctahedron) {
  for (int it : {1, 3}) {
    check(data("tetrahedron.off"), Method::Loop, it);
    check(data("octahedron.off"), Method::Loop, it);
  }
}

TEST(SubdivisionOracle, Sqrt3TetrahedronAndOctahedron) {
  for (int it : {1, 3}) {
    check(data("tetrahedron.off"), Method::Sqrt3, it);
    check(data("octahedron.off"), Method::Sqrt3, it);
  }
}

TEST(SubdivisionOracle, DooSabin) {
  for (int it : {1, 3}) {
    check(data("cube.off"), Method::DooSabin, it);
    check(data("tetrahedron.off"), Method::DooSabin, it);
    check(data("octahedron.off"), Method::DooSabin, it);
  }
}
