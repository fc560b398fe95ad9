// Oracle: the subdivision rule schemes of tools/data/rules with their position expressions give
// CGAL::Subdivision_method_3's meshes (isomorphic, positions within 1e-9 relative) on the small
// closed meshes of tools/data, after 1 and 3 iterations.
#include <initializer_list>

#include "model/expr/tests/subdivision_oracle.hpp"

using namespace gmr::expr::oracle;

namespace {

std::string data(const char* name) { return source_dir() + "/tools/data/" + name; }

// check after 1 and after 3 iterations on each mesh of tools/data.
void check_meshes(Method m, std::initializer_list<const char*> meshes) {
  for (int it : {1, 3})
    for (const char* mesh : meshes) check(data(mesh), m, it);
}

}  // namespace

TEST(SubdivisionOracle, CatmullClarkCube) { check_meshes(Method::CatmullClark, {"cube.off"}); }

TEST(SubdivisionOracle, CatmullClarkTriangles) {
  check_meshes(Method::CatmullClark, {"tetrahedron.off", "octahedron.off"});
}

TEST(SubdivisionOracle, LoopTetrahedronAndOctahedron) {
  check_meshes(Method::Loop, {"tetrahedron.off", "octahedron.off"});
}

TEST(SubdivisionOracle, Sqrt3TetrahedronAndOctahedron) {
  check_meshes(Method::Sqrt3, {"tetrahedron.off", "octahedron.off"});
}

TEST(SubdivisionOracle, DooSabin) {
  check_meshes(Method::DooSabin, {"cube.off", "tetrahedron.off", "octahedron.off"});
}
