// The `gmr` binary on hostile input: every case gets a located message and exit 2 (or 1 for a
// negative verdict), never a crash, a silent success or library-internal text.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tools/tests/cli_fixture.hpp"

using namespace gmr::cli_test;

namespace {

// square.json (a valid 2-G-map with positions) with `edit` applied, written to `path`.
void write_edited_square(const fs::path& path, const std::function<void(nlohmann::json&)>& edit) {
  nlohmann::json j = nlohmann::json::parse(gmr::io::read_text_file(test_data("square.json")));
  edit(j);
  std::ofstream(path) << j.dump();
}

}  // namespace

TEST_F(Cli, DeeplyNestedEmbeddingValueIsRefused) {
  // 50,000 nested arrays as a position value: refused at the nesting limit by every command.
  const fs::path in = dir / "deep.json";
  std::string text = gmr::io::read_text_file(test_data("square.json"));
  const std::string first = "\"value\": [0, 0, 0]";
  const size_t at = text.find(first);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, first.size(), "\"value\": " + std::string(50000, '[') + std::string(50000, ']'));
  std::ofstream(in) << text;
  const std::vector<std::string> commands = {"info " + q(in), "validate " + q(in),
                                             "convert " + q(in) + " " + q(dir / "out" / "x.json"),
                                             "signature " + q(in) + " --flags position"};
  for (const std::string& cmd : commands) {
    const Result r = run(cmd);
    EXPECT_EQ(r.code, 2) << cmd << "\n" << r.err;
    EXPECT_NE(r.err.find("nesting deeper than 100"), std::string::npos) << cmd << "\n" << r.err;
    EXPECT_NE(r.err.find(in.string() + ":$.embeddings[0].values[0].value"), std::string::npos)
        << r.err;
  }
  EXPECT_EQ(outputs(), 0u);
}

TEST_F(Cli, DeclaredDartCountIsCheckedBeforeAllocating) {
  const fs::path in = dir / "darts_100000000.json";
  write_edited_square(in, [&](nlohmann::json& j) { j["darts"] = 100000000; });
  const auto start = std::chrono::steady_clock::now();
  expect_bad_input("info " + q(in), in.string() + ":$.alpha.0",
                   "expected 100000000 entries (one per dart), found 8");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
  // Above the dart limit (model/map_io/read_limits.hpp), refused at the declaration.
  const fs::path huge = dir / "darts_4294967294.json";
  write_edited_square(huge, [&](nlohmann::json& j) { j["darts"] = 4294967294u; });
  expect_bad_input("info " + q(huge), huge.string() + ":$.darts",
                   "the input needs 4294967294 darts, above the limit");
}

TEST_F(Cli, MalformedNumbersAndKeysAreLocated) {
  const fs::path overflow = dir / "overflow.json";
  std::ofstream(overflow) << "{\"format\": \"gmr.gmap\", \"version\": 1e999}";
  expect_bad_input("info " + q(overflow), overflow.string() + ":1:", "1e999");
  EXPECT_EQ(run("info " + q(overflow)).err.find("json.exception"), std::string::npos);

  const fs::path twice = dir / "twice.json";
  std::ofstream(twice) << "{\"format\": \"gmr.gmap\", \"format\": \"gmr.gmap\"}";
  expect_bad_input("info " + q(twice), twice.string() + ":$.format", "duplicate member \"format\"");

  const fs::path real = dir / "real_index.json";
  write_edited_square(real, [](nlohmann::json& j) { j["alpha"]["0"][0] = 1.0; });
  expect_bad_input("info " + q(real), real.string() + ":$.alpha.0[0]",
                   "expected a dart index (an integer), found the number 1.0");
}

TEST_F(Cli, PositionValuesAreValidated) {
  for (const auto& [name, value] :
       std::vector<std::pair<std::string, nlohmann::json>>{{"text", "abc"}, {"pair", {1, 2}}}) {
    const fs::path in = dir / (name + ".json");
    write_edited_square(
        in, [&](nlohmann::json& j) { j["embeddings"][0]["values"][0]["value"] = value; });
    const Result r = run("validate " + q(in));
    EXPECT_EQ(r.code, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("a position must be an array [x, y, z]"), std::string::npos) << r.out;
  }
  const fs::path bare = dir / "bare.json";
  write_edited_square(bare, [](nlohmann::json& j) { j.erase("embeddings"); });
  expect_bad_input("convert " + q(bare) + " " + q(dir / "out" / "x.off"),
                   (dir / "out" / "x.off").string(),
                   "no \"position\" embedding: off output needs vertex coordinates");
  EXPECT_EQ(outputs(), 0u);
}

TEST_F(Cli, WriteErrorsOnStandardOutputFail) {
  for (const std::string& cmd : {"info " + q(tools_data("cube.off")),
                                 "convert " + q(tools_data("cube.off")) + " - --to json",
                                 "dot " + q(tools_data("cube.off"))}) {
    const int status =
        std::system((q(gmr_bin()) + " " + cmd + " >/dev/full 2>" + q(dir / "stderr")).c_str());
    EXPECT_EQ(WEXITSTATUS(status), 2) << cmd;
    EXPECT_NE(gmr::io::read_text_file(dir / "stderr").find("standard output: write failed"),
              std::string::npos)
        << cmd;
  }
}

TEST_F(Cli, OutputThroughASymbolicLinkKeepsTheLink) {
  const fs::path target = dir / "out" / "target.json";
  fs::create_symlink("target.json", dir / "out" / "link.json");
  const Result r = run("convert " + q(tools_data("cube.off")) + " " + q(dir / "out" / "link.json"));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(dir / "out" / "link.json"));
  EXPECT_TRUE(fs::is_regular_file(target));
  EXPECT_EQ(outputs(), 2u);
}

TEST_F(Cli, CommandWordsAndOptionValues) {
  expect_bad_input("foo", "usage", "unknown command 'foo' (commands: info, validate");
  Result r = run("help");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("Usage: gmr"), std::string::npos) << r.out;
  r = run("help info");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("Usage: gmr info"), std::string::npos) << r.out;
  expect_bad_input("validate --limit -1 " + q(test_data("square.json")), "--limit",
                   "expected a non-negative integer");
  expect_bad_input("apply " + q(source_dir() / "checker/tests/data/F5_fig319a_unsew.json") + " " +
                       q(tools_data("cube.off")) + " --match a=0,a=1",
                   "--match", "given twice");
  expect_bad_input("info " + q(dir / "rules.jme"), "rules.jme",
                   "Jerboa rule file (.jme) holds rules, not a map");
  // Long user input is quoted abbreviated.
  r = run("fold " + q(test_data("square.json")) + " --dart 0 --orbit '<0," +
          std::string(100000, '1') + ">'");
  EXPECT_EQ(r.code, 2);
  EXPECT_LT(r.err.size(), 1000u) << r.err.size();
  EXPECT_NE(r.err.find("characters ...]"), std::string::npos) << r.err.substr(0, 500);
}

TEST_F(Cli, RejectedRulesAreRefusedUnlessForced) {
  const fs::path rule = source_dir() / "tools/tests/data/swap_face_links.json";
  // Topology only (the cube's positions would also be reported merged: docs/embeddings.md).
  const std::string apply =
      "apply " + q(rule) + " " + q(tools_data("cube.off")) + " --hook 0 --no-embeddings";
  Result r = run(apply + " -o " + q(dir / "out" / "x.json"));
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("rule \"swap_face_links\" is rejected by the checker (2 error(s))"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("[C-word] C(0,2)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
  EXPECT_EQ(outputs(), 0u);
  // Forced: applied with a warning; the broken result is listed up to --limit with a count.
  r = run(apply + " --force --limit 3");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("warning: applying rule \"swap_face_links\", which the checker rejects"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.out.find("INVALID"), std::string::npos) << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 5) << r.out;
  EXPECT_NE(r.out.find("  ... and 13 more (--limit)"), std::string::npos) << r.out;
}

TEST_F(Cli, JerboaRuleNamesAreUniqueAndPreconditionsReported) {
  std::string jme = gmr::io::read_text_file(tools_data("jerboa/JerboaTrackingOrbit.jme"));
  const std::string renamed = "name=\"DeleteEdge\"";
  ASSERT_NE(jme.find(renamed), std::string::npos);
  jme.replace(jme.find(renamed), renamed.size(), "name=\"DeleteFace\"");
  const fs::path twice = dir / "twice.jme";
  std::ofstream(twice) << jme;
  expect_bad_input("check " + q(twice), twice.string() + ":",
                   "two rules named \"DeleteFace\" (lines ");

  // A rule with a precondition: the application says it is not evaluated.
  jme = gmr::io::read_text_file(tools_data("jerboa/JerboaTrackingOrbit.jme"));
  const size_t rule_at = jme.find("name=\"SubdivQuad\"");
  ASSERT_NE(rule_at, std::string::npos);
  const size_t pre = jme.find("<precondition>", rule_at),
               pre_end = jme.find("</precondition>", rule_at);
  ASSERT_LT(pre, pre_end);
  jme.replace(pre, pre_end - pre, "<precondition><![CDATA[return false;]]>");
  const fs::path fake = dir / "fake.jme";
  std::ofstream(fake) << jme;
  const fs::path cube3 = dir / "cube3.json";
  ASSERT_EQ(run("convert " + q(tools_data("polycube.voxels.json")) + " " + q(cube3)).code, 0);
  Result r = run("apply " + q(fake) + " --rule SubdivQuad " + q(cube3) + " --hook 0");
  EXPECT_NE(r.err.find("rule \"SubdivQuad\" has a Jerboa precondition; gmr does not evaluate it"),
            std::string::npos)
      << r.err;
  r = run("check " + q(fake));
  EXPECT_NE(r.out.find("S-precondition"), std::string::npos) << r.out;
}

TEST_F(Cli, LargeDrawingsAreRefusedBeforeGraphviz) {
  const fs::path torus = dir / "torus.json";
  ASSERT_EQ(run("demo --out " + q(dir / "demo")).code, 0);
  fs::copy_file(dir / "demo" / "torus.json", torus);  // 576 darts
  expect_bad_input("dot " + q(torus) + " --max-darts 500 -o " + q(dir / "out" / "t.svg"),
                   (dir / "out" / "t.svg").string(),
                   "the map has 576 darts; Graphviz is not asked to lay out more than 500");
  EXPECT_EQ(outputs(), 0u);
  // DOT text has no limit.
  EXPECT_EQ(run("dot " + q(torus) + " --max-darts 500 -o " + q(dir / "out" / "t.dot")).code, 0);
}

TEST_F(Cli, SurfacesMeetVolumeRulesThroughLift) {
  const std::string apply = "apply " + q(tools_data("jerboa/JerboaTrackingOrbit.jme")) +
                            " --rule SubdivQuad " + q(tools_data("cube.off")) + " --hook 0";
  expect_bad_input(apply, "cube.off", "the scheme rewrites 3-G-maps, the map is a 2-G-map: --lift");
  // The fixture's rules write "pos" and "color", the cube holds "position": topology only.
  const Result r = run(apply + " --lift --json --no-embeddings");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["darts"], 192);
  EXPECT_EQ(j["change"]["cells"], nlohmann::json::parse("[[8,12,6,1],[26,48,24,1]]"));
  EXPECT_EQ(j["change"]["euler"], nlohmann::json::parse("[1,1]"));
}

TEST_F(Cli, ApplyReportsTheChangeInCells) {
  const Result r = run("apply " + q(source_dir() / "tools/data/rules/quad_subdivision.json") + " " +
                       q(tools_data("cube.off")) + " --hook 0");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(
      r.out.find(
          "cells 0:8 1:12 2:6 -> 0:26 1:48 2:24, components 1 -> 1, Euler characteristic 2 -> 2"),
      std::string::npos)
      << r.out;
}

TEST_F(Cli, OffVariantsOfCgalDataAreRead) {
  const fs::path coff = dir / "tetra.off";
  std::ofstream(coff)
      << "#this is a comment\nCOFF\n4 4 0\n0 0 0 192 192 192 255\n1 0 0 192 192 192 255\n"
         "0 1 0 192 192 192 255\n0 0 1 192 192 192 255\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n";
  const Result r = run("info " + q(coff));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("cells:       0:4 1:6 2:4"), std::string::npos) << r.out;
}

TEST_F(Cli, InputSizeAndDartLimitsFailFast) {
  // `gmr ARGS` with the environment settings ENV: exit code 2 and `message` on standard error.
  auto expect_refused = [&](const std::string& env, const std::string& args,
                            const std::string& message) {
    const int status = std::system(
        (env + " " + q(gmr_bin()) + " " + args + " >/dev/null 2>" + q(dir / "stderr")).c_str());
    const std::string err = gmr::io::read_text_file(dir / "stderr");
    EXPECT_EQ(WEXITSTATUS(status), 2) << env << " " << args;
    EXPECT_NE(err.find(message), std::string::npos) << err;
  };
  expect_refused("GMR_MAX_DARTS=40", "info " + q(tools_data("cube.off")),
                 "the input needs 48 darts, above the limit of 40 (set GMR_MAX_DARTS to raise it)");
  expect_refused("GMR_MAX_DARTS=7", "info " + q(test_data("square.json")),
                 "square.json:$.darts: the input needs 8 darts");
  expect_refused("GMR_MAX_INPUT_BYTES=100", "info " + q(tools_data("cube.off")),
                 "above the limit of 100 bytes (set GMR_MAX_INPUT_BYTES to raise it)");
  expect_refused("GMR_MAX_INPUT_BYTES=100", "info --from off - <" + q(tools_data("cube.off")),
                 "-: input of more than 100 bytes");
  expect_refused("GMR_MAX_DARTS=lots", "info " + q(tools_data("cube.off")),
                 "GMR_MAX_DARTS: expected a non-negative integer, found \"lots\"");
}

TEST_F(Cli, StructuralProblemsOfJerboaRulesAreLocated) {
  std::string jme = gmr::io::read_text_file(tools_data("jerboa/JerboaTrackingOrbit.jme"));
  const size_t arc = jme.find("dim=\"", jme.find("<arc ", jme.find("name=\"SubdivQuad\"")));
  jme.replace(arc, 6, "dim=\"9");
  const fs::path bad = dir / "bad.jme";
  std::ofstream(bad) << jme;
  const std::string apply =
      "apply " + q(bad) + " --rule SubdivQuad " + q(tools_data("cube.off")) + " --lift --hook 0";
  Result r = run(apply);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("S-dim-range"), std::string::npos) << r.err;
  r = run(apply + " --force");  // the forced application's warning, then the located error
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("gmr: error: " + bad.string() +
                       ": rule SubdivQuad: R arc 0: arc dimension 9 outside 0..3"),
            std::string::npos)
      << r.err;
}
