// OFF in/out and OBJ out (model/io_off.hpp, io_obj.hpp, face_list.hpp): counts, comments and
// counts-line variants, malformed lines located by line number, non-manifold input rejected,
// read -> write -> read isomorphism, consistent face orientation.
#include "model/map_io/off.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <map>

#include "model/core/builders.hpp"
#include "model/core/orbit.hpp"
#include "model/core/sew.hpp"
#include "model/core/signature.hpp"
#include "model/core/validity.hpp"
#include "model/map_io/obj.hpp"
#include "model/map_io/read_file.hpp"
#include "model/testing/source_tree.hpp"

using namespace gmr;
using namespace gmr::io;

namespace {

std::string source_dir() { return gmr::testing::source_path("."); }

void expect_error(const std::string& text, ErrorCode code, const std::string& location,
                  const std::string& what = "") {
  try {
    read_off(text, "t.off");
    FAIL() << "no error; expected " << location;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), code) << e.what();
    EXPECT_EQ(e.location(), location) << e.what();
    EXPECT_NE(e.message().find(what), std::string::npos) << e.what();
  }
}

// Every edge of a consistently oriented face list is traversed once in each direction.
bool consistently_oriented(const FaceList& fl) {
  std::map<std::pair<uint32_t, uint32_t>, int> seen;
  for (const auto& f : fl.faces)
    for (size_t p = 0; p < f.size(); ++p)
      if (++seen[{f[p], f[(p + 1) % f.size()]}] > 1) return false;
  return true;
}

const char* kTetra = "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n";

}  // namespace

TEST(IoOff, ReadsCube) {
  const EmbeddedMap m = read_off_file(source_dir() + "/tools/data/cube.off");
  EXPECT_TRUE(is_valid(m.map));
  EXPECT_EQ(m.map.size(), 48u);
  EXPECT_EQ(count_all_cells(m.map), (std::vector<size_t>{8, 12, 6}));
  EXPECT_TRUE(is_isomorphic(m.map, make_cube()));
  EXPECT_TRUE(m.position().check(m.map).empty());
  EXPECT_EQ(m.position().orbit_type(), (OrbitType{1, 2}));
}

TEST(IoOff, AcceptsCommentsBlankLinesAndCountVariants) {
  const std::string variants[] = {
      kTetra,
      "# a tetrahedron\n\nOFF # header\n4 4\n\n0 0 0\n1 0 0 # v1\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 "
      "3\n3 1 2 3\n3 2 0 3",
      "OFF 4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1 255 0 0\n3 0 1 3 1\n3 1 2 3 0.1 0.2 0.3 1\n3 "
      "2 0 3\r\n",
  };
  for (const auto& text : variants) {
    const EmbeddedMap m = read_off(text);
    EXPECT_TRUE(is_isomorphic(m.map, make_tetrahedron())) << text;
    EXPECT_EQ(m.position().get(2), (Vec3{0, 1, 0})) << text;
  }
}

TEST(IoOff, HeaderVariantsOfCgalData) {
  // COFF (vertex colours, RGB or RGBA), NOFF (normals), 4OFF (homogeneous), STCNOFF (all).
  const std::string faces = "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n";
  const std::string variants[] = {
      "COFF\n4 4 0\n0 0 0 192 192 192 255\n1 0 0 1 2 3 4\n0 1 0 9 9 9\n0 0 1 0 0 0 0\n" + faces,
      "NOFF\n4 4 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n0 0 1 0 0 1\n" + faces,
      "4OFF\n4 4 0\n0 0 0 1\n2 0 0 2\n0 0.5 0 0.5\n0 0 -3 -3\n" + faces,
      "STCNOFF\n4 4 0\n0 0 0 0 0 1 1 1 1 0.5 0.5\n1 0 0 0 0 1 1 1 1 1 0 0\n0 1 0 0 0 1 1 1 1 1 0 "
      "0\n"
      "0 0 1 0 0 1 1 1 1 1 0 0\n" +
          faces,
  };
  for (const auto& text : variants) {
    const EmbeddedMap m = read_off(text);
    EXPECT_TRUE(is_isomorphic(m.map, make_tetrahedron())) << text;
    EXPECT_EQ(m.position().get(2), (Vec3{0, 1, 0})) << text;
  }
  expect_error("COFF\n1 0\n0 0 0 1 1\n", ErrorCode::Parse, "t.off:3",
               "\"x y z r g b [a]\" (6 or 7 numbers)");
  expect_error("NOFF\n1 0\n0 0 0 1 1 x\n", ErrorCode::Parse, "t.off:3", "a normal component");
  expect_error("4OFF\n1 0\n1 1 1 0\n", ErrorCode::Parse, "t.off:3", "w = 0");
  expect_error("OFF BINARY\n", ErrorCode::Parse, "t.off:1", "binary OFF");
  expect_error("CNOFFX\n", ErrorCode::Parse, "t.off:1", "[ST][C][N][4]OFF");
  expect_error("NCOFF\n", ErrorCode::Parse, "t.off:1", "[ST][C][N][4]OFF");
}

TEST(IoOff, MalformedLinesAreLocated) {
  expect_error("", ErrorCode::Parse, "t.off:1", "expected the header");
  expect_error("OFFX\n", ErrorCode::Parse, "t.off:1", "expected the header \"[ST][C][N][4]OFF\"");
  expect_error("OFF\n# no counts\n", ErrorCode::Parse, "t.off:2", "end of file");
  expect_error("OFF\n4\n", ErrorCode::Parse, "t.off:2", "counts");
  expect_error("OFF\n4 x\n", ErrorCode::Parse, "t.off:2", "\"x\"");
  expect_error("OFF\n2 0\n0 0 0\n1 0\n", ErrorCode::Parse, "t.off:4", "3 numbers");
  expect_error("OFF\n2 0\n0 0 0\n1 0 zz\n", ErrorCode::Parse, "t.off:4", "coordinate z");
  expect_error("OFF\n1 0\n0 nan 0\n", ErrorCode::Parse, "t.off:3", "finite");
  expect_error("OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n", ErrorCode::Parse, "t.off:6", "lists 2");
  expect_error("OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", ErrorCode::Parse, "t.off:6", "at least 3");
  expect_error("OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", ErrorCode::Parse, "t.off:6",
               "vertex index 3 out of range");
  expect_error("OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -2\n", ErrorCode::Parse, "t.off:6", "\"-2\"");
  expect_error("OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n", ErrorCode::Parse, "t.off:6", "repeated");
  expect_error("OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 1 2\n", ErrorCode::Parse, "t.off:6",
               "2 extra value(s)");
  expect_error("OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n", ErrorCode::Parse, "t.off:7",
               "after the last face");
  expect_error("OFF\n3 2\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", ErrorCode::Parse, "t.off:6",
               "face 1 of 2");
}

TEST(IoOff, NonManifoldInputIsRejectedByName) {
  try {
    read_off_file(source_dir() + "/model/map_io/tests/data/nonmanifold_edge.off");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::NonManifold);
    EXPECT_EQ(e.location(), source_dir() + "/model/map_io/tests/data/nonmanifold_edge.off:11");
    EXPECT_NE(e.message().find("non-manifold edge"), std::string::npos) << e.what();
    EXPECT_NE(e.message().find("lines 9, 10, 11"), std::string::npos) << e.what();
  }
  try {
    read_off_file(source_dir() + "/model/map_io/tests/data/pinched_vertex.off");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::NonManifold);
    EXPECT_EQ(e.location(),
              source_dir() + "/model/map_io/tests/data/pinched_vertex.off:4");  // vertex 0's line
    EXPECT_NE(e.message().find("non-manifold vertex"), std::string::npos) << e.what();
  }
}

TEST(IoOff, ReadWriteReadIsIsomorphic) {
  for (const std::string& text :
       {std::string(kTetra), read_text_file(source_dir() + "/tools/data/cube.off")}) {
    const EmbeddedMap a = read_off(text);
    const std::string written = write_off(a.map, a.position());
    const EmbeddedMap b = read_off(written);
    EXPECT_TRUE(is_isomorphic(a.map, b.map));
    EXPECT_EQ(write_off(b.map, b.position()), written);
    // Same positions at the same darts (the faces are written back in the same order).
    a.map.for_each_dart([&](Dart d) { EXPECT_EQ(a.position().get(d), b.position().get(d)); });
  }
}

TEST(IoOff, OpenSurfacesAndConsistentOrientation) {
  // An open grid: boundary edges survive the round trip.
  FaceList grid;
  for (uint32_t y = 0; y < 3; ++y)
    for (uint32_t x = 0; x < 3; ++x) grid.vertices.push_back({double(x), double(y), 0});
  for (uint32_t y = 0; y < 2; ++y)
    for (uint32_t x = 0; x < 2; ++x)
      grid.faces.push_back({3 * y + x, 3 * y + x + 1, 3 * y + x + 4, 3 * y + x + 3});
  const EmbeddedMap g = map_from_face_list(grid);
  EXPECT_TRUE(is_isomorphic(g.map, make_grid(2, 2)));
  const FaceList back = face_list_from_map(g.map, g.position());
  EXPECT_EQ(back.faces.size(), 4u);
  EXPECT_EQ(back.num_edges, 12u);
  EXPECT_TRUE(consistently_oriented(back));
  const EmbeddedMap g2 = read_off(write_off(back));
  EXPECT_TRUE(is_isomorphic(g.map, g2.map));
  // The cube read from a file with one face flipped is written back consistently oriented.
  const EmbeddedMap cube = read_off(
      "OFF\n8 6\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"
      "4 0 2 3 1\n4 6 7 5 4\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n");
  EXPECT_TRUE(consistently_oriented(face_list_from_map(cube.map, cube.position())));
  // A torus (orientable, closed): built with faces in a scrambled orientation, written
  // consistently.
  FaceList torus;
  const uint32_t w = 4, h = 3;
  for (uint32_t k = 0; k < w * h; ++k) torus.vertices.push_back({double(k), 0, 0});
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      std::vector<uint32_t> f{y * w + x, y * w + (x + 1) % w, ((y + 1) % h) * w + (x + 1) % w,
                              ((y + 1) % h) * w + x};
      if ((x + y) % 2) std::reverse(f.begin(), f.end());
      torus.faces.push_back(f);
    }
  const EmbeddedMap t = map_from_face_list(torus);
  EXPECT_TRUE(is_isomorphic(t.map, make_torus(w, h)));
  EXPECT_FALSE(consistently_oriented(torus));
  EXPECT_TRUE(consistently_oriented(face_list_from_map(t.map, t.position())));
}

TEST(IoOff, WriterRequirements) {
  const Map cube = make_cube();
  PositionEmbedding none(kPositionName, OrbitType{1, 2});
  try {
    write_off(cube, none);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Schema);
    EXPECT_EQ(e.location(), "dart 0");
  }
  EXPECT_THROW(write_off(make_stacked_cubes(), none), Error);  // not a 2-G-map
  // A dangling edge: its face is not a closed polygon.
  Map edge = make_free_edge(2);
  PositionEmbedding pos(kPositionName, OrbitType{1, 2});
  pos.set(edge, 0, {0, 0, 0});
  pos.set(edge, 1, {1, 0, 0});
  try {
    write_off(edge, pos);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidMap);
    EXPECT_NE(e.message().find("open face"), std::string::npos);
  }
  // A square face is written; a 2-gon is refused.
  Map square = make_polygon(4);
  PositionEmbedding sq(kPositionName, OrbitType{1, 2});
  for (Dart rep : orbit_representatives(square, OrbitType{1, 2}))
    sq.set(square, rep, {double(rep), 0, 0});
  EXPECT_EQ(face_list_from_map(square, sq).faces.size(), 1u);
  Map digon = make_polygon(2);
  PositionEmbedding dg(kPositionName, OrbitType{1, 2});
  for (Dart rep : orbit_representatives(digon, OrbitType{1, 2}))
    dg.set(digon, rep, {double(rep), 0, 0});
  EXPECT_THROW(write_off(digon, dg), Error);
}

TEST(IoObj, WritesVerticesAndOneBasedFaces) {
  const EmbeddedMap m = read_off(kTetra);
  const std::string obj = write_obj(m.map, m.position());
  EXPECT_NE(obj.find("\nv 0 0 0\nv 0 1 0\n"), std::string::npos) << obj;
  size_t faces = 0, vertices = 0;
  for (size_t p = 0; (p = obj.find('\n', p)) != std::string::npos; ++p) {
    if (obj.compare(p + 1, 2, "f ") == 0) ++faces;
    if (obj.compare(p + 1, 2, "v ") == 0) ++vertices;
  }
  EXPECT_EQ(faces, 4u);
  EXPECT_EQ(vertices, 4u);
  EXPECT_NE(obj.find("f 1 2 3\n"), std::string::npos)
      << obj;  // face (0 2 1) re-read as vertices 1 2 3
}

// A map a face list cannot describe is refused by the writer (it used to be written and read back
// as another map: found by the off_roundtrip property). A "pillow" (two quads glued along their
// four edges, a sphere) round-trips; with one edge unsewn, two edges join the same two vertices.
TEST(IoOff, WriterRefusesUnfaithfulMaps) {
  Map g = surface_from_faces({{0, 1, 3, 2}, {1, 0, 2, 3}}, 4);
  ASSERT_TRUE(is_valid(g));
  ASSERT_EQ(euler_characteristic(g), 2);
  PositionEmbedding pos(kPositionName, OrbitType{1, 2});
  double k = 0;
  for (Dart rep : orbit_representatives(g, OrbitType{1, 2}))
    pos.set(g, rep, Vec3{k, 2 * k, 0}), k += 1;
  const EmbeddedMap back = read_off(write_off(g, pos));
  EXPECT_TRUE(is_isomorphic(g, back.map));
  gmr::unsew(g, 2, 0);
  ASSERT_TRUE(is_valid(g));
  try {
    write_off(g, pos);
    FAIL() << "an unfaithful OFF was written";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::NonManifold);
    EXPECT_NE(std::string(e.what()).find("two edges join the same two vertices"),
              std::string::npos);
  }
}

TEST(IoObj, ReadsFacesWithTextureAndNormalReferences) {
  // The OBJ the writer produces, and a hand-written one with groups, vt/vn and negative indices.
  const EmbeddedMap tetra = read_off(kTetra);
  const EmbeddedMap back = read_obj(write_obj(tetra.map, tetra.position()), "t.obj");
  EXPECT_TRUE(is_isomorphic(back.map, make_tetrahedron()));
  const std::string text =
      "# tetrahedron\nmtllib t.mtl\no tetra\nv 0 0 0\nv 1 0 0\nv 0 1 0 0.5 0.5 0.5\nv 0 0 1 "
      "1.0\nvt 0 0\nvn 0 0 1\n"
      "g side\ns off\nusemtl red\nf 1/1 3/1 2/1\nf 1//1 2//1 4//1\nf -3/1/1 -2/1/1 -1/1/1\nf 3 1 "
      "4\n";
  const EmbeddedMap m = read_obj(text, "t.obj");
  EXPECT_TRUE(is_isomorphic(m.map, make_tetrahedron()));
  EXPECT_EQ(m.position().get(m.map.darts()[0]), (Vec3{0, 0, 0}));
}

TEST(IoObj, MalformedLinesAreLocated) {
  auto error_of = [](const std::string& text) {
    try {
      read_obj(text, "t.obj");
    } catch (const Error& e) {
      return e.location() + ": " + e.message();
    }
    return std::string("no error");
  };
  EXPECT_NE(error_of("v 0 0\n").find("t.obj:1: expected a vertex"), std::string::npos);
  EXPECT_NE(error_of("v 0 0 x\n").find("t.obj:1: expected a finite number, found \"x\""),
            std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nv 1 0 0\nf 1 2\n").find("t.obj:3: a face needs at least 3 vertices"),
            std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n")
                .find("t.obj:4: vertex index 4 out of range (3 vertices"),
            std::string::npos);
  EXPECT_NE(
      error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n").find("t.obj:4: expected a vertex index"),
      std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2\n").find("degenerate face"),
            std::string::npos);
  EXPECT_NE(error_of("\n\nbogus 1 2\n").find("t.obj:3: unknown OBJ statement \"bogus\""),
            std::string::npos);
  // A non-manifold edge is named with the lines of its three faces.
  const std::string fan =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 1 1 1\nf 1 2 3\nf 1 2 4\nf 1 2 5\n";
  EXPECT_NE(error_of(fan).find("faces at lines 6, 7, 8"), std::string::npos) << error_of(fan);
}
