// `gmr query-replace` and `gmr patterns check` run as a user would.
#include <fstream>

#include "model/core/orbit.hpp"
#include "model/core/validity.hpp"
#include "model/map_io/map_json.hpp"
#include "model/testing/scratch_dir.hpp"
#include "tools/tests/cli_fixture.hpp"

namespace gmr::cli_test {
namespace {

using CliReplace = Cli;

// The polycube of tools/data as the gmr binary reads it (converted to gmr.gmap JSON).
EmbeddedMap load_voxels_map() {
  const fs::path tmp = gmr::testing::scratch_path("gmr_cli_replace_polycube") += ".json";
  const std::string cmd = q(gmr_bin()) + " convert " + q(tools_data("polycube.voxels.json")) + " " +
                          q(tmp) + " >/dev/null";
  if (std::system(cmd.c_str()) != 0) throw std::runtime_error("gmr convert failed");
  EmbeddedMap f = io::read_map_json_file(tmp);
  fs::remove(tmp);
  return f;
}

fs::path patterns(const std::string& set) { return tools_data("patterns/" + set); }

TEST_F(CliReplace, SubdividesTheCubeFacesWithTheConformalSet) {
  const fs::path out = dir / "out" / "cube.json";
  const Result r = run("query-replace " + q(patterns("conformal-faces")) + " " +
                       q(tools_data("cube.off")) + " --split-edges 2 --flag-all -o " + q(out));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("6 faces, 6 replaced, 0 unmatched"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("split4: 6"), std::string::npos) << r.out;
  const EmbeddedMap f = io::read_map_json_file(out);
  EXPECT_TRUE(is_valid(f.map));
  EXPECT_EQ(count_cells(f.map, 2), 24u);
  EXPECT_EQ(f.map.size(), 192u);
  ASSERT_NE(f.find("flag"), nullptr);
  // The result, with its flags, is the boundary of the 2x2x2 pattern: signed by `gmr signature`.
  EXPECT_EQ(run("signature " + q(out) + " --flags flag").code, 0);
  EXPECT_EQ(run("validate " + q(out)).code, 0);
  // Positions are carried (face centres by mean value coordinates): the result converts to OFF.
  ASSERT_NE(f.find("position"), nullptr);
  EXPECT_EQ(run("convert " + q(out) + " " + q(dir / "out" / "cube.off")).code, 0);
}

TEST_F(CliReplace, UnflaggedFacesDoNotMatchFlaggedPatternsAndAreReported) {
  const fs::path out = dir / "out" / "cube.json";
  const Result r = run("query-replace " + q(patterns("conformal-faces")) + " " +
                       q(tools_data("cube.off")) + " --split-edges 2 --json -o " + q(out));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["replaced"], 0);
  EXPECT_EQ(j["unmatched"], 6);
  EXPECT_EQ(j["mode"], "unoriented");
  EXPECT_EQ(j["unmatched_darts"].size(), 6u);
}

TEST_F(CliReplace, OrientedModeOnTheTetrahedron) {
  const fs::path off = dir / "tet.off";
  std::ofstream(off)
      << "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
  const fs::path out = dir / "out" / "tet.json";
  const Result r = run("query-replace " + q(patterns("tet-to-hex")) + " " + q(off) +
                       " --split-edges 2 --flag-all --oriented --json -o " + q(out));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["mode"], "oriented");
  EXPECT_EQ(j["replaced"], 4);
  EXPECT_EQ(j["matched"]["triangle3"], 4);
  const EmbeddedMap f = io::read_map_json_file(out);
  EXPECT_TRUE(is_valid(f.map));
  EXPECT_EQ(f.map.size(), 96u);
  EXPECT_EQ(count_cells(f.map, 2), 12u);
}

// Hexahedral subdivision of a polycube in two calls: faces (after the e-pattern), then volumes.
TEST_F(CliReplace, SubdividesAPolycubeFacesThenVolumes) {
  const fs::path faces = dir / "out" / "faces.json", volumes = dir / "out" / "volumes.json";
  const EmbeddedMap in = load_voxels_map();
  const auto c = count_all_cells(in.map);
  Result r = run("query-replace " + q(patterns("hex-subdivision")) + " " +
                 q(tools_data("polycube.voxels.json")) + " --split-edges 2 --flag-all --json -o " +
                 q(faces));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["matched"]["split4"], c[2]);
  r = run("query-replace " + q(patterns("hex-subdivision")) + " " + q(faces) +
          " --cells 3 --json -o " + q(volumes));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["matched"]["hex8"], c[3]);
  const EmbeddedMap f = io::read_map_json_file(volumes);
  EXPECT_TRUE(is_valid(f.map));
  EXPECT_EQ(count_cells(f.map, 3), 8 * c[3]);
  EXPECT_EQ(count_cells(f.map, 0), c[0] + c[1] + c[2] + c[3]);
}

TEST_F(CliReplace, BadInputsExitTwoAndLeaveNoOutput) {
  const fs::path bad = dir / "bad";
  fs::create_directories(bad);
  std::ofstream(bad / "closed.json")
      << "{\"format\":\"gmr.gmap\",\"version\":1,\"kind\":\"gmap\",\"dimension\":2,"
         "\"darts\":2,\"alpha\":{\"0\":[1,0],\"1\":[1,0],\"2\":[1,0]}}";
  const std::string out = q(dir / "out" / "x.json");
  expect_bad_input("query-replace " + q(bad) + " " + q(tools_data("cube.off")) + " -o " + out,
                   "closed.json", "no boundary");
  expect_bad_input(
      "query-replace " + q(dir / "none") + " " + q(tools_data("cube.off")) + " -o " + out, "none");
  expect_bad_input("query-replace " + q(patterns("conformal-faces")) + " " +
                       q(tools_data("cube.off")) + " --cells 3 -o " + out,
                   "", "3-cells");
  expect_bad_input("query-replace " + q(patterns("conformal-faces")) + " " +
                       q(tools_data("cube.off")) + " --cells 4 -o " + out,
                   "usage");
  expect_bad_input("query-replace " + q(patterns("conformal-faces")) + " " +
                       q(tools_data("cube.off")) + " --split-edges 4000000000 -o " + out,
                   "--split-edges", "not in range");
  expect_bad_input("query-replace " + q(patterns("conformal-faces")) + " " +
                       q(tools_data("cube.off")) + " --cells 3 --split-edges 2 -o " + out,
                   "", "3-cells");
  EXPECT_EQ(outputs(), 0u);
}

// The conformal volume patterns, generated (one cone per oriented class) and checked: 325 classes,
// none missing, no duplicate in oriented mode; in unoriented mode the 99 chiral pairs are
// duplicates. A non-empty output folder and an unknown set are refused.
TEST_F(CliReplace, GeneratesTheConformalVolumePatterns) {
  const fs::path out = dir / "out" / "hex-conformal";
  Result r = run("patterns generate hex-conformal " + q(out) + " --oriented");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("325 v-patterns"), std::string::npos) << r.out;
  EXPECT_EQ(std::distance(fs::directory_iterator(out), fs::directory_iterator()), 325);
  r = run("patterns check " + q(out) + " --configurations hex-conformal --oriented --json");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["oriented"]["classes"], 325);
  EXPECT_EQ(j["oriented"]["missing_classes"], 0);
  EXPECT_EQ(j["oriented"]["duplicates"].size(), 0u);
  EXPECT_EQ(j["unoriented"]["classes"], 226);
  EXPECT_EQ(j["unoriented"]["missing_classes"], 0);
  EXPECT_EQ(j["unoriented"]["duplicates"].size(), 99u);
  expect_bad_input("patterns generate hex-conformal " + q(out), out.string(),
                   "not an empty folder");
  expect_bad_input("patterns generate hex-edges " + q(dir / "out" / "other"), "generate",
                   "unknown pattern set");
  EXPECT_FALSE(fs::exists(dir / "out" / "other"));
}

TEST_F(CliReplace, PatternsCheckCoverageVerdicts) {
  Result r =
      run("patterns check " + q(patterns("conformal-faces")) + " --configurations square-edges");
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("15 configurations, 5 classes, 0 classes missing"), std::string::npos)
      << r.out;
  r = run("patterns check " + q(patterns("tet-to-hex")) +
          " --configurations square-edges --oriented --json");
  EXPECT_EQ(r.code, 1) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["oriented"]["missing_classes"], 5);
  EXPECT_EQ(j["complete"], false);
  r = run("patterns check " + q(patterns("tet-to-hex")) + " --configurations triangle-edges");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("edges {0}"), std::string::npos) << r.out;
  expect_bad_input("patterns check " + q(patterns("tet-to-hex")) + " --configurations nonsense",
                   "--configurations", "square-edges");
}

TEST_F(CliReplace, HelpAndTheMarchingCubesClassCounts) {
  EXPECT_EQ(run("query-replace --help").code, 0);
  EXPECT_EQ(run("patterns check --help").code, 0);
  const Result r = run("patterns check " + q(patterns("hex-subdivision")) +
                       " --configurations marching-cubes --json");
  EXPECT_EQ(r.code, 1) << r.err;  // no marching-cubes pattern in this set
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["oriented"]["classes"], 29);
  EXPECT_EQ(j["unoriented"]["classes"], 26);
  EXPECT_EQ(j["oriented"]["configurations"], 654);
}

TEST_F(CliReplace, PatternsCheckReportsDuplicates) {
  const fs::path set = dir / "dups";
  fs::create_directories(set);
  fs::copy_file(patterns("conformal-faces") / "split4.json", set / "a.json");
  fs::copy_file(patterns("conformal-faces") / "split4.json", set / "b.json");
  const Result r = run("patterns check " + q(set) + " --json");
  EXPECT_EQ(r.code, 1) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["unoriented"]["duplicates"].size(), 1u);
  EXPECT_EQ(j["unoriented"]["duplicates"][0], nlohmann::json::parse("[\"a\",\"b\"]"));
  EXPECT_EQ(j["oriented"]["duplicates"].size(), 1u);
}

}  // namespace
}  // namespace gmr::cli_test
