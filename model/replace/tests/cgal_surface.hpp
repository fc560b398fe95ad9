// A closed triangle mesh of CGAL's data (Debian's libcgal-demo ships them in data.tar.gz; the
// tests unpack the ones they use into the build directory, nothing is committed) with CGAL's AABB
// tree, as the box test of adaptive hexahedral meshing.
#pragma once
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "model/replace/adaptive_hex_meshing.hpp"
#include "model/testing/cgal_data.hpp"

namespace gmr::replace::testing {

using gmr::testing::cgal_mesh;

class CgalSurface {
 public:
  using K = CGAL::Simple_cartesian<double>;
  using Mesh = CGAL::Surface_mesh<K::Point_3>;
  using Tree =
      CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;

  explicit CgalSurface(const std::string& off) {
    std::ifstream in(off);
    in >> mesh_;
    tree_ = std::make_unique<Tree>(faces(mesh_).first, faces(mesh_).second, mesh_);
    tree_->accelerate_distance_queries();
  }
  size_t triangles() const { return mesh_.number_of_faces(); }
  bool closed() const { return CGAL::is_closed(mesh_); }
  // The cube around the mesh's bounding box, 5 % larger on each side.
  std::pair<Vec3, double> root_cube() const {
    const CGAL::Bbox_3 b = tree_->bbox();
    const double size =
        1.1 * std::max({b.xmax() - b.xmin(), b.ymax() - b.ymin(), b.zmax() - b.zmin()});
    const Vec3 c{(b.xmin() + b.xmax()) / 2, (b.ymin() + b.ymax()) / 2, (b.zmin() + b.zmax()) / 2};
    return {Vec3{c[0] - size / 2, c[1] - size / 2, c[2] - size / 2}, size};
  }
  BoxTest box_test() const {
    return [this](const Vec3& lo, const Vec3& hi) {
      return tree_->do_intersect(CGAL::Bbox_3(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]));
    };
  }

 private:
  Mesh mesh_;
  std::unique_ptr<Tree> tree_;
};

}  // namespace gmr::replace::testing
