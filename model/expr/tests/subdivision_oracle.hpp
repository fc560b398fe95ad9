// Shared by the CGAL oracle tests of the subdivision rule schemes: gmr's subdivision (rule scheme
// with expressions, applied at every dart) and CGAL::Subdivision_method_3 on a Surface_mesh, and
// the comparison of the two results: a bijection of the vertices by position (every coordinate
// within 1e-9 relative) under which the faces are the same cycles (up to rotation and reversal),
// i.e. isomorphic meshes with equal positions.
#pragma once
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "model/core/embedded_map.hpp"
#include "model/expr/compiled_scheme.hpp"
#include "model/expr/propagation.hpp"
#include "model/map_io/face_list.hpp"
#include "model/map_io/off.hpp"
#include "model/rule_io/scheme_json.hpp"

namespace gmr::expr::oracle {

using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

inline std::string source_dir() {
  const char* s = std::getenv("GMR_SOURCE_DIR");
  return s ? s : ".";
}

enum class Method { CatmullClark, Loop, Sqrt3, DooSabin };

inline const char* rule_file(Method m) {
  switch (m) {
    case Method::CatmullClark:
      return "quad_subdivision.json";
    case Method::Loop:
      return "loop_subdivision.json";
    case Method::Sqrt3:
      return "sqrt3_subdivision.json";
    case Method::DooSabin:
      return "doo_sabin_subdivision.json";
  }
  return "";
}

// gmr: `iterations` times the scheme at every dart, with positions.
inline io::FaceList gmr_subdivide(const std::string& off, Method method, int iterations) {
  const scheme::RuleScheme s =
      io::read_scheme_file(source_dir() + "/tools/data/rules/" + rule_file(method));
  const scheme::SchemeEngine engine(s);
  const CompiledScheme cs = compile_scheme(s);
  EmbeddedMap m = io::read_off_file(off);
  for (int k = 0; k < iterations; ++k) {
    EmbeddingPropagation p(cs, m);
    const auto all =
        scheme::apply_everywhere(engine, m.map, {.keep_tables = false, .observer = &p});
    EXPECT_GT(all.count(), 0u);
    EXPECT_EQ(p.issue_count(), 0u) << (p.issues().empty() ? "" : p.issues()[0].message);
  }
  return io::face_list_from_map(m.map, m.find("position")->values);
}

inline io::FaceList cgal_subdivide(const std::string& off, Method method, int iterations) {
  Mesh mesh;
  std::ifstream in(off);
  EXPECT_TRUE(CGAL::IO::read_OFF(in, mesh)) << off;
  namespace SM = CGAL::Subdivision_method_3;
  const auto np = CGAL::parameters::number_of_iterations(iterations);
  switch (method) {
    case Method::CatmullClark:
      SM::CatmullClark_subdivision(mesh, np);
      break;
    case Method::Loop:
      SM::Loop_subdivision(mesh, np);
      break;
    case Method::Sqrt3:
      SM::Sqrt3_subdivision(mesh, np);
      break;
    case Method::DooSabin:
      SM::DooSabin_subdivision(mesh, np);
      break;
  }
  io::FaceList fl;
  std::vector<uint32_t> index(mesh.number_of_vertices() + mesh.number_of_removed_vertices(), 0);
  for (auto v : mesh.vertices()) {
    index[v.idx()] = static_cast<uint32_t>(fl.vertices.size());
    const auto& p = mesh.point(v);
    fl.vertices.push_back({p.x(), p.y(), p.z()});
  }
  for (auto f : mesh.faces()) {
    std::vector<uint32_t> face;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      face.push_back(index[v.idx()]);
    fl.faces.push_back(face);
  }
  return fl;
}

inline bool close(double a, double b) {
  return std::fabs(a - b) <= 1e-9 * std::max({1.0, std::fabs(a), std::fabs(b)});
}

// A face as a canonical cycle: the smallest rotation of the sequence or of its reverse.
inline std::vector<uint32_t> canonical(std::vector<uint32_t> f) {
  auto least_rotation = [](std::vector<uint32_t> c) {
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    return c;
  };
  std::vector<uint32_t> a = least_rotation(f);
  std::reverse(f.begin(), f.end());
  std::vector<uint32_t> b = least_rotation(f);
  return std::min(a, b);
}

// Compares the two meshes (see the header comment); `what` names the case in failures.
inline void expect_same_mesh(const io::FaceList& ours, const io::FaceList& cgal,
                             const std::string& what) {
  ASSERT_EQ(ours.vertices.size(), cgal.vertices.size()) << what;
  ASSERT_EQ(ours.faces.size(), cgal.faces.size()) << what;
  // Vertex bijection by position: CGAL's vertices sorted by x, a window search per vertex.
  std::vector<uint32_t> order(cgal.vertices.size());
  for (uint32_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(),
            [&](uint32_t a, uint32_t b) { return cgal.vertices[a][0] < cgal.vertices[b][0]; });
  std::vector<uint32_t> to_cgal(ours.vertices.size(), UINT32_MAX);
  std::vector<bool> used(cgal.vertices.size(), false);
  size_t unmatched = 0;
  for (uint32_t v = 0; v < ours.vertices.size(); ++v) {
    const Vec3& p = ours.vertices[v];
    const double tol = 1e-9 * std::max(1.0, std::fabs(p[0]));
    auto it = std::lower_bound(order.begin(), order.end(), p[0] - tol,
                               [&](uint32_t a, double x) { return cgal.vertices[a][0] < x; });
    for (; it != order.end() && cgal.vertices[*it][0] <= p[0] + tol; ++it) {
      const Vec3& q = cgal.vertices[*it];
      if (!used[*it] && close(p[0], q[0]) && close(p[1], q[1]) && close(p[2], q[2])) {
        to_cgal[v] = *it;
        used[*it] = true;
        break;
      }
    }
    if (to_cgal[v] == UINT32_MAX && ++unmatched <= 3)
      ADD_FAILURE() << what << ": vertex " << v << " (" << p[0] << ", " << p[1] << ", " << p[2]
                    << ") has no CGAL vertex within 1e-9 relative";
  }
  ASSERT_EQ(unmatched, 0u) << what;
  std::multiset<std::vector<uint32_t>> a, b;
  for (const auto& f : ours.faces) {
    std::vector<uint32_t> g;
    for (uint32_t v : f) g.push_back(to_cgal[v]);
    a.insert(canonical(g));
  }
  for (const auto& f : cgal.faces) b.insert(canonical(f));
  EXPECT_TRUE(a == b) << what << ": same vertices, different faces";
}

inline void check(const std::string& off, Method method, int iterations) {
  const std::string what =
      off + ", " + rule_file(method) + ", " + std::to_string(iterations) + " iteration(s)";
  expect_same_mesh(gmr_subdivide(off, method, iterations), cgal_subdivide(off, method, iterations),
                   what);
}

}  // namespace gmr::expr::oracle
