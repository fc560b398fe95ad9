// `gmr verify` and `gmr validate-condition` (tools/cli/cmd_verify.cpp, cmd_validate_condition.cpp):
// verdicts and exit codes 0/1/2, the counterexample files, plug-ins that fail.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "model/map_io/read_file.hpp"
#include "model/testing/scratch_dir.hpp"
#include "model/testing/source_tree.hpp"

namespace fs = std::filesystem;

namespace {
std::string q(const fs::path& p) { return "'" + p.string() + "'"; }
fs::path source_dir() { return gmr::testing::source_path("."); }
std::string gmr_bin() { return gmr::testing::build_artifact("GMR_BIN"); }
// A condition plug-in built for the tests (checker/smt/CMakeLists.txt).
std::string plugin(const std::string& stem) {
  return gmr::testing::build_artifact("GMR_PLUGIN_DIR") + "/lib" + stem + ".so";
}
struct Result {
  int code;
  std::string out, err;
};

class CliVerify : public ::testing::Test {
 protected:
  fs::path dir;
  void SetUp() override {
    dir = gmr::testing::scratch_path(
        "gmr_cli_verify_" +
        std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  Result run(const std::string& args) {
    const std::string cmd = q(gmr_bin()) + " " + args + " >" + q(dir / "stdout") + " 2>" +
                            q(dir / "stderr") + " </dev/null";
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, gmr::io::read_text_file(dir / "stdout"),
            gmr::io::read_text_file(dir / "stderr")};
  }
};
}  // namespace

TEST_F(CliVerify, PreservingRule) {
  const Result r = run("verify " + q(source_dir() / "checker/tests/data/F5_fig319a_sew.json") +
                       " --bound 5 --engine both");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("no 2-G-map of at most 5 darts"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("engine smt"), std::string::npos);
  EXPECT_NE(r.out.find("engine enum"), std::string::npos);
}

TEST_F(CliVerify, CounterexampleFiles) {
  const Result r =
      run("verify " + q(source_dir() / "checker/tests/data/F3_ex37_non_orientation.json") +
          " -k 4 --json -o " + q(dir / "cex.json") + " --dot " + q(dir / "cex.dot"));
  EXPECT_EQ(r.code, 1) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["format"], "gmr.verify");
  EXPECT_EQ(doc["verdict"], "breaks");
  const auto cex = nlohmann::json::parse(gmr::io::read_text_file(dir / "cex.json"));
  EXPECT_EQ(cex["format"], "gmr.counterexample");
  EXPECT_EQ(cex["version"], 1);
  EXPECT_EQ(cex["G"]["format"], "gmr.gmap");
  EXPECT_FALSE(cex["violations"].empty());
  EXPECT_FALSE(cex["offending_darts"].empty());
  const std::string dot = gmr::io::read_text_file(dir / "cex.dot");
  EXPECT_NE(dot.find("fillcolor=\"#ff6b6b\""), std::string::npos) << dot;
}

// The counterexample's drawing takes its format from the extension: SVG is rendered by Graphviz,
// and a format that is not a drawing is refused before the sweep, with nothing written.
TEST_F(CliVerify, CounterexampleDrawingByExtension) {
  const std::string rule = q(source_dir() / "checker/tests/data/F3_ex37_non_orientation.json");
  EXPECT_EQ(run("verify " + rule + " -k 4 --dot " + q(dir / "cex.svg")).code, 1);
  const std::string svg = gmr::io::read_text_file(dir / "cex.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos) << svg.substr(0, 200);
  EXPECT_EQ(svg.find("digraph"), std::string::npos);
  const Result bad = run("verify " + rule + " -k 4 --dot " + q(dir / "cex.json"));
  EXPECT_EQ(bad.code, 2) << bad.err;
  EXPECT_NE(bad.err.find("drawings are written as dot, svg or png"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir / "cex.json"));
}

TEST_F(CliVerify, RuleSchemeByInstantiation) {
  const Result r = run("verify " + q(source_dir() / "tools/data/jerboa/JerboaTrackingOrbit.jme") +
                       " --rule DeleteEdge --bound 6 --json");
  EXPECT_EQ(r.code, 1) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["kind"], "scheme");
  EXPECT_EQ(doc["counterexample"]["instance_of"], "DeleteEdge");
}

TEST_F(CliVerify, BadInput) {
  EXPECT_EQ(run("verify " + q(source_dir() / "checker/tests/data/F3_ex37_non_orientation.json") +
                " --engine z3")
                .code,
            2);
  EXPECT_EQ(run("verify " + q(dir / "missing.json")).code, 2);
}

TEST_F(CliVerify, ValidateConditionWrongVariantExits1) {
  const Result r =
      run("validate-condition --condition wrong-incident-without-dangling --labels 0,1 --max-nodes "
          "1 --bound 2 --json");
  EXPECT_EQ(r.code, 1) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["format"], "gmr.condition-validation");
  EXPECT_EQ(doc["sound"], false);
  EXPECT_TRUE(doc["smallest_unsound"]["counterexample"]["gluing_fails"].get<bool>());
  EXPECT_TRUE(r.err.empty()) << "no progress output when standard error is not a terminal: "
                             << r.err;
}

TEST_F(CliVerify, ValidateConditionThesisExits0) {
  const Result r =
      run("validate-condition --condition thesis --labels 0,1 --max-nodes 1 --bound 3 --shard 1/2");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("sound: yes"), std::string::npos) << r.out;
}

TEST_F(CliVerify, ValidateConditionSymbolicEngine) {
  const Result ok =
      run("validate-condition --condition thesis --labels 0,1 --max-nodes 3 --bound 5 --engine "
          "symbolic");
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_NE(ok.out.find("every rule of the family at once (1466908 rules)"), std::string::npos)
      << ok.out;
  const Result bad = run(
      "validate-condition --condition wrong-orientation-dropped --labels 0 --max-nodes 3 --bound 4 "
      "--engine symbolic --json -o " +
      q(dir / "sym.json"));
  EXPECT_EQ(bad.code, 1) << bad.err;
  const auto doc = nlohmann::json::parse(bad.out);
  EXPECT_EQ(doc["engine"], "symbolic");
  EXPECT_EQ(doc["sound"], false);
  EXPECT_EQ(doc["smallest_unsound"]["counterexample"]["G"]["darts"], 3);
  EXPECT_TRUE(fs::exists(dir / "sym.json"));
  EXPECT_EQ(run("validate-condition --merge " + q(dir / "sym.json")).code, 2);
  // Cycle pairs: C_r through the checker's lemmas; the variant without ij-completion is incomplete.
  const Result cyc =
      run("validate-condition --condition thesis --labels 0,1,2 --max-nodes 2 --bound 4 --engine "
          "symbolic");
  EXPECT_EQ(cyc.code, 0) << cyc.err;
  EXPECT_NE(cyc.out.find("component patterns tabulated by the concrete checker"), std::string::npos)
      << cyc.out;
  const Result wrong = run(
      "validate-condition --condition wrong-cycle-without-completion --labels 0,1,2 --max-nodes 2 "
      "--bound 4 --engine symbolic --json");
  EXPECT_EQ(wrong.code, 1) << wrong.err;
  const auto wdoc = nlohmann::json::parse(wrong.out);
  EXPECT_EQ(wdoc["complete"], false);
  EXPECT_TRUE(wdoc.contains("smallest_incomplete"));
  EXPECT_GT(wdoc["cycle_patterns"].get<int>(), 0);
  EXPECT_EQ(wdoc["cycle_lemmas"].get<int>(), 0);
  // Plug-ins and shards are refused.
  EXPECT_EQ(
      run("validate-condition --condition thesis --labels 0,1 --shard 0/2 --engine symbolic").code,
      2);
  EXPECT_EQ(run(std::string("validate-condition --plugin ") + q(plugin("crashing_condition")) +
                " --engine symbolic")
                .code,
            2);
}

TEST_F(CliVerify, CrashingPluginExits2NamingPluginAndRule) {
  const Result r = run(std::string("validate-condition --plugin ") +
                       q(plugin("crashing_condition")) + " --labels 0 --max-nodes 2");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("crashing_condition"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("while evaluating rule rule"), std::string::npos) << r.err;
  EXPECT_EQ(run(std::string("validate-condition --plugin ") + q(dir / "nothing.so")).code, 2);
  EXPECT_EQ(run("validate-condition --condition no-such-condition").code, 2);
  EXPECT_EQ(run("validate-condition --condition thesis --shard 3/2").code, 2);
}

TEST_F(CliVerify, ValidateSchemeConditionOnSchemeFiles) {
  const std::string rules = (source_dir() / "tools/data/rules").string();
  const Result r =
      run("validate-condition --condition scheme-thesis --bound 3 --json --schemes " +
          q(rules + "/face_triangulation.json") + " " + q(rules + "/quad_subdivision.json"));
  EXPECT_EQ(r.code, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["format"], "gmr.scheme-condition-validation");
  EXPECT_EQ(doc["schemes"], 2);
  EXPECT_EQ(doc["holds"], 2);
  EXPECT_EQ(doc["sound"], true);
  EXPECT_EQ(run("validate-condition --condition scheme-thesis").code, 2);  // no --schemes
  EXPECT_EQ(run("validate-condition --condition thesis --schemes " +
                q(rules + "/face_triangulation.json"))
                .code,
            2);
  EXPECT_EQ(run("validate-condition --condition scheme-thesis --schemes " +
                q(source_dir() / "checker/tests/data/F3_ex37_non_orientation.json"))
                .code,
            2);  // a concrete rule
}

TEST_F(CliVerify, SchemePluginOnSchemeFiles) {
  const std::string rules = (source_dir() / "tools/data/rules").string();
  const Result r = run(std::string("validate-condition --plugin ") +
                       q(plugin("full_degree_scheme_condition")) + " --bound 3 --json --schemes " +
                       q(rules + "/face_triangulation.json") + " " + q(rules + "/sew2.json"));
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["condition"], "full-degree");
  EXPECT_EQ(doc["schemes"], 2);
  EXPECT_EQ(r.code, doc["sound"].get<bool>() && doc["complete"].get<bool>() ? 0 : 1) << r.err;
  // A plug-in without the scheme entry point, with --schemes: exit 2 naming the symbol.
  const Result bad = run(std::string("validate-condition --plugin ") +
                         q(plugin("crashing_condition")) + " --schemes " + q(rules + "/sew2.json"));
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("gmr_scheme_condition_v1"), std::string::npos) << bad.err;
}

TEST_F(CliVerify, HangingPluginExits2AfterTheEvaluationTimeLimit) {
  const Result r =
      run(std::string("validate-condition --plugin ") + q(plugin("hanging_condition")) +
          " --labels 0 --max-nodes 1 --eval-timeout 0.5");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("hanging_condition"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("did not return within the per-evaluation time limit of 0.5 s while "
                       "evaluating rule rule"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(run("validate-condition --condition thesis --eval-timeout -1").code, 2);
}

TEST_F(CliVerify, ShardsMergeIntoTheWholeSweep) {
  const std::string sweep =
      "validate-condition --condition wrong-incident-without-dangling --labels 0,1 --max-nodes 2 "
      "--bound 3 ";
  EXPECT_EQ(run(sweep + "--shard 0/2 -o " + q(dir / "s0.json")).code, 1);
  EXPECT_EQ(run(sweep + "--shard 1/2 -o " + q(dir / "s1.json")).code, 1);
  const Result whole = run(sweep + "--json");
  const Result merged =
      run("validate-condition --merge " + q(dir / "s0.json") + " " + q(dir / "s1.json"));
  EXPECT_EQ(merged.code, 1) << merged.err;
  const auto a = nlohmann::json::parse(whole.out), b = nlohmann::json::parse(merged.out);
  for (const char* key : {"rules", "holds", "fails", "vacuous", "unsound", "incomplete"})
    EXPECT_EQ(a[key], b[key]) << key;
  EXPECT_EQ(a["smallest_unsound"]["index"], b["smallest_unsound"]["index"]);
  EXPECT_EQ(b["shard"], "0,1/2");
  EXPECT_EQ(run("validate-condition --merge " + q(dir / "s0.json") + " " + q(dir / "s0.json")).code,
            2);
}
