// The `gmr` binary (tools/cli/) on good and malformed inputs: exit codes 0/1/2, error messages
// "gmr: error: <location>: <message>" naming the JSON path or line, and no output file left
// behind by a failed command. The binary's path comes from the build (GMR_BIN), the data files
// from GMR_SOURCE_DIR.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "model/core/orbit.hpp"
#include "model/core/signature.hpp"
#include "model/map_io/map_json.hpp"
#include "model/map_io/off.hpp"
#include "model/map_io/read_file.hpp"
#include "tools/tests/cli_fixture.hpp"

using namespace gmr;
using namespace gmr::io;
using namespace gmr::cli_test;
namespace fs = std::filesystem;

TEST_F(Cli, HelpForEverySubcommand) {
  Result r = run("--help");
  EXPECT_EQ(r.code, 0);
  for (const char* sub :
       {"info", "validate", "convert", "dot", "signature", "demo", "fold", "infer"}) {
    EXPECT_NE(r.out.find(sub), std::string::npos) << sub;
    const Result h = run(std::string(sub) + " --help");
    EXPECT_EQ(h.code, 0) << sub;
    EXPECT_NE(h.out.find("Usage"), std::string::npos) << sub;
  }
}

TEST_F(Cli, UsageErrorsExitTwo) {
  expect_bad_input("", "usage", "subcommand");
  expect_bad_input("frobnicate", "usage");
  expect_bad_input("info", "usage", "file");
  expect_bad_input("info " + q(tools_data("cube.off")) + " --bogus", "usage", "--bogus");
  expect_bad_input("info " + q(dir / "missing.json"), (dir / "missing.json").string(),
                   "cannot open");
  expect_bad_input("info " + q(dir / "noext"), (dir / "noext").string(), "--from");
  expect_bad_input("info " + q(tools_data("cube.off")) + " --from xyz", "--from", "unknown format");
}

TEST_F(Cli, InfoOnOffAndJson) {
  Result r = run("info " + q(tools_data("cube.off")));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("cells:       0:8 1:12 2:6"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("euler:       2"), std::string::npos) << r.out;
  r = run("info --json " + q(test_data("square.json")));
  EXPECT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["darts"], 8);
  EXPECT_EQ(j["cells"], nlohmann::json::array({4, 4, 1}));
  EXPECT_EQ(j["boundary_cells"], 4);
  EXPECT_EQ(j["closed"], false);
  EXPECT_EQ(j["embeddings"][0]["values"], 4);
}

TEST_F(Cli, MalformedInputsNameTheirLocation) {
  expect_bad_input("info " + q(test_data("bad_syntax.json")), "bad_syntax.json:4:8",
                   "malformed JSON");
  expect_bad_input("validate " + q(test_data("wrong_format.json")), "wrong_format.json:$.format",
                   "gmr.gmap");
  expect_bad_input("validate " + q(test_data("dart_out_of_range.json")),
                   "dart_out_of_range.json:$.alpha.1[3]", "dart index 7 out of range");
  expect_bad_input("info " + q(test_data("nonmanifold_edge.off")), "nonmanifold_edge.off:11",
                   "non-manifold edge");
  expect_bad_input("info " + q(test_data("pinched_vertex.off")), "pinched_vertex.off:4",
                   "non-manifold vertex");
  expect_bad_input("info " + q(test_data("bad_line.off")), "bad_line.off:5", "3 numbers");
}

TEST_F(Cli, ValidateVerdicts) {
  Result r = run("validate " + q(test_data("square.json")));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("valid 2-G-map"), std::string::npos);
  r = run("validate " + q(test_data("invalid_gmap.json")));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.out.find("4 violation(s)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("cycle at dart 0"), std::string::npos) << r.out;
  r = run("validate --json " + q(test_data("invalid_gmap.json")));
  EXPECT_EQ(r.code, 1);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["valid"], false);
  EXPECT_EQ(j["violations"].size(), 4u);
  EXPECT_EQ(j["violations"][0]["constraint"], "cycle");
  EXPECT_EQ(j["violations"][0]["dart"], 0);
  // An orbit without an embedding value is reported on a valid map.
  std::string text = read_text_file(test_data("square.json"));
  text.replace(text.find("      {\"dart\": 5, \"value\": [0, 1, 0]}\n"), 0, "");
  const size_t at = text.find(",\n      {\"dart\": 5");
  text.erase(at, text.find('}', at) + 1 - at);
  std::ofstream(dir / "partial.json") << text;
  r = run("validate " + q(dir / "partial.json"));
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("embedding 'position' at dart"), std::string::npos) << r.out;
}

TEST_F(Cli, ConvertRoundTripsAndFormats) {
  const fs::path json = dir / "out/cube.json", off = dir / "out/cube.off",
                 obj = dir / "out/cube.obj";
  EXPECT_EQ(run("convert " + q(tools_data("cube.off")) + " " + q(json)).code, 0);
  EXPECT_EQ(run("convert " + q(json) + " " + q(off)).code, 0);
  EXPECT_EQ(run("convert " + q(json) + " " + q(obj)).code, 0);
  const EmbeddedMap a = read_off_file(tools_data("cube.off")), b = read_off_file(off);
  EXPECT_TRUE(is_isomorphic(a.map, b.map));
  EXPECT_TRUE(is_isomorphic(a.map, read_map_json_file(json).map));
  EXPECT_NE(read_text_file(obj).find("\nf "), std::string::npos);
  for (const char* ext : {"dot", "svg", "png"}) {
    const fs::path p = dir / "out" / (std::string("square.") + ext);
    EXPECT_EQ(run("convert " + q(test_data("square.json")) + " " + q(p)).code, 0) << ext;
    const std::string bytes = read_text_file(p);
    const std::string e = ext;
    const bool ok = e == "dot"   ? bytes.rfind("graph", 0) == 0
                    : e == "svg" ? bytes.find("<svg") != std::string::npos
                                 : bytes.substr(1, 3) == "PNG";
    EXPECT_TRUE(ok) << ext;
  }
  // --from / --to overrides and standard input/output.
  Result r = run("convert - - --from off --to json", tools_data("cube.off"));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(read_map_json(r.out).map.size(), 48u);
  EXPECT_EQ(outputs(), 6u);
}

TEST_F(Cli, FailedCommandsLeaveNoOutput) {
  const fs::path out = dir / "out/x.json";
  expect_bad_input("convert " + q(test_data("bad_syntax.json")) + " " + q(out),
                   "bad_syntax.json:4:8");
  expect_bad_input("convert " + q(test_data("nonmanifold_edge.off")) + " " + q(out),
                   "nonmanifold_edge.off:11");
  expect_bad_input("convert " + q(test_data("square.json")) + " " + q(dir / "out/x.txt"), "x.txt",
                   "--to");
  // OFF output needs positions: the 2-G-map of invalid_gmap.json has none.
  expect_bad_input("convert " + q(test_data("invalid_gmap.json")) + " " + q(dir / "out/x.off"), "",
                   "\"position\"");
  expect_bad_input("convert " + q(test_data("square.json")) + " " + q(dir / "out/missing/x.json"),
                   "missing/x.json");
  EXPECT_EQ(outputs(), 0u);
  // A failed conversion keeps the previous content of the destination.
  std::ofstream(out) << "previous";
  expect_bad_input("convert " + q(test_data("dart_out_of_range.json")) + " " + q(out),
                   "$.alpha.1[3]");
  EXPECT_EQ(read_text_file(out), "previous");
  EXPECT_EQ(outputs(), 1u);
}

TEST_F(Cli, DotAndSignature) {
  Result r = run("dot " + q(test_data("square.json")));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("graph \"gmap\" {", 0), 0u);
  EXPECT_EQ(r.out.find("0 -- 0"), std::string::npos);
  r = run("dot --loops " + q(test_data("square.json")));
  EXPECT_NE(r.out.find("0 -- 0 [color=blue]"), std::string::npos) << r.out;
  EXPECT_EQ(run("dot " + q(test_data("square.json")) + " -o " + q(dir / "out/sq.svg")).code, 0);
  expect_bad_input("dot " + q(test_data("square.json")) + " -o " + q(dir / "out/sq.obj"), "sq.obj",
                   "dot, svg or png");

  const Result s1 = run("signature " + q(tools_data("cube.off")));
  EXPECT_EQ(s1.code, 0) << s1.err;
  ASSERT_EQ(run("convert " + q(tools_data("cube.off")) + " " + q(dir / "out/cube.json")).code, 0);
  const Result s2 = run("signature " + q(dir / "out/cube.json"));
  EXPECT_EQ(s1.out, s2.out);
  EXPECT_EQ(s1.out.rfind("gmap2:[", 0), 0u) << s1.out;
  const Result f = run("signature --json --flags position " + q(dir / "out/cube.json"));
  EXPECT_EQ(f.code, 0) << f.err;
  EXPECT_NE(nlohmann::json::parse(f.out)["signature"],
            nlohmann::json(s1.out.substr(0, s1.out.size() - 1)));
  expect_bad_input("signature --flags colour " + q(dir / "out/cube.json"), "--flags",
                   "no embedding");
}

TEST_F(Cli, Demo) {
  const Result r = run("demo --json --out " + q(dir / "out/demo"));
  EXPECT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["ok"], true);
  ASSERT_EQ(j["objects"].size(), 5u);
  EXPECT_EQ(j["objects"][0]["darts"], 96);
  EXPECT_EQ(j["objects"][0]["cells"], nlohmann::json::array({12, 20, 11, 2}));
  for (const char* f :
       {"stacked_cubes.dot", "stacked_cubes.svg", "cube.dot", "cube.svg", "cube.obj", "torus.obj"})
    EXPECT_TRUE(fs::exists(dir / "out/demo" / f)) << f;
  // The torus OBJ round-trips into the torus of the builders.
  EXPECT_EQ(run("info " + q(dir / "out/demo/torus.json")).code, 0);
}

fs::path rule_data(const std::string& name) { return tools_data("rules/" + name); }
fs::path checker_data(const std::string& name) {
  return source_dir() / "checker/tests/data" / name;
}

TEST_F(Cli, DotOfRulesAndSchemes) {
  // A rule scheme: labels "n0 <_,1,2>", arcs coloured per dimension, double-bordered hook.
  Result r = run("dot " + q(rule_data("quad_subdivision.json")));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("digraph \"quad_subdivision\" {", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("label=\"n0 <0,1,2>\", peripheries=2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("label=\"n0 <_,1,2>\""), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("color=red"), std::string::npos);
  EXPECT_NE(r.out.find("color=black"), std::string::npos);
  // A concrete rule with κ arcs.
  r = run("dot --kappa " + q(checker_data("F5_fig319a_sew.json")));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("subgraph cluster_L"), std::string::npos);
  EXPECT_NE(r.out.find("subgraph cluster_R"), std::string::npos);
  EXPECT_NE(r.out.find("color=pink, style=dashed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("color=blue"), std::string::npos) << r.out;
  // A rejected rule: the offending added node d is highlighted with its code.
  r = run("dot --check " + q(checker_data("F1_ex34_weak_incident.json")));
  EXPECT_EQ(r.code, 0) << r.err;
  const size_t at = r.out.find("R3 [label=\"d\"");
  ASSERT_NE(at, std::string::npos) << r.out;
  const std::string line = r.out.substr(at, r.out.find('\n', at) - at);
  EXPECT_NE(line.find("I-added-node"), std::string::npos) << line;
  EXPECT_NE(line.find("style=\"bold,filled\""), std::string::npos) << line;
  // Rendering and .jme files.
  EXPECT_EQ(run("dot --check " + q(rule_data("sew2.json")) + " -o " + q(dir / "out/sew2.svg")).code,
            0);
  EXPECT_NE(read_text_file(dir / "out/sew2.svg").find("<svg"), std::string::npos);
  EXPECT_EQ(run("dot --kappa " + q(checker_data("F1_ex34_weak_incident.json")) + " -o " +
                q(dir / "out/f1.png"))
                .code,
            0);
  EXPECT_EQ(read_text_file(dir / "out/f1.png").substr(1, 3), "PNG");
  r = run("dot " + q(tools_data("jerboa/JerboaTrackingOrbit.jme")) + " --rule " + "NOTARULE");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("rules: "), std::string::npos) << r.err;
  expect_bad_input("dot " + q(tools_data("jerboa/JerboaTrackingOrbit.jme")),
                   "JerboaTrackingOrbit.jme", "--rule NAME");
  expect_bad_input("dot --kappa " + q(rule_data("sew2.json")), "sew2.json", "concrete rule");
  expect_bad_input("dot --check " + q(test_data("square.json")), "square.json", "rule files");
  EXPECT_EQ(outputs(), 2u);
}

// `gmr check --json` prints one gmr.check document (docs/check-format.md) for a concrete rule, a
// rule scheme and a .jme batch alike: format, version, subject and ok first.
TEST_F(Cli, CheckJsonIsOneFormat) {
  struct Case {
    fs::path file;
    std::string subject;
    int code;
  };
  const std::vector<Case> cases = {
      {checker_data("F5_fig319a_unsew.json"), "rule", 0},
      {checker_data("F1_ex34_weak_incident.json"), "rule", 1},
      {rule_data("quad_subdivision.json"), "scheme", 0},
      {tools_data("jerboa/JerboaTrackingOrbit.jme"), "modeler", -1},
  };
  for (const auto& c : cases) {
    const Result r = run("check --json " + q(c.file));
    if (c.code >= 0) {
      EXPECT_EQ(r.code, c.code) << c.file << r.err;
    }
    const auto j = nlohmann::ordered_json::parse(r.out);
    ASSERT_GE(j.size(), 4u) << c.file;
    auto it = j.begin();
    EXPECT_EQ(it.key(), "format");
    EXPECT_EQ(*it, "gmr.check") << c.file;
    EXPECT_EQ((++it).key(), "version");
    EXPECT_EQ(*it, 1) << c.file;
    EXPECT_EQ((++it).key(), "subject");
    EXPECT_EQ(*it, c.subject) << c.file;
    EXPECT_EQ((++it).key(), "ok");
    EXPECT_EQ(it->get<bool>(), r.code == 0) << c.file;
    EXPECT_EQ(j["file"], c.file.string());
    if (c.subject == "modeler") {
      ASSERT_FALSE(j["reports"].empty());
      for (const auto& rep : j["reports"]) {
        EXPECT_FALSE(rep.contains("format"));
        EXPECT_TRUE(rep["ok"].is_boolean());
      }
    }
  }
}

TEST_F(Cli, DotOfJerboaRule) {
  Result r = run("check --json " + q(tools_data("jerboa/JerboaTrackingOrbit.jme")));
  ASSERT_NE(r.out, "");
  const auto j = nlohmann::json::parse(r.out);
  const std::string name = j["reports"][0]["rule"];
  r = run("dot --check " + q(tools_data("jerboa/JerboaTrackingOrbit.jme")) + " --rule " + q(name));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("subgraph cluster_L"), std::string::npos) << r.out;
}

// A .jme file nesting 20,000 elements: a located error (tinyxml2's depth limit), not a crash.
TEST_F(Cli, DeeplyNestedJmeIsALocatedError) {
  const fs::path deep = dir / "deep.jme";
  {
    std::ofstream f(deep);
    f << "<jerboamodelereditor>\n<modeler name='M' dimension='2'>\n<rules>\n<rule name='r'>\n";
    for (int i = 0; i < 20000; ++i) f << "<x>";
    for (int i = 0; i < 20000; ++i) f << "</x>";
    f << "\n</rule>\n</rules>\n</modeler>\n</jerboamodelereditor>\n";
  }
  expect_bad_input("check " + q(deep), "deep.jme:5: malformed XML", "nested too deeply");
  expect_bad_input("check --json " + q(deep), "deep.jme:5: malformed XML", "nested too deeply");
}

TEST_F(Cli, CheckAndApplyConcreteRule) {
  EXPECT_EQ(run("check " + q(checker_data("F5_fig319a_unsew.json"))).code, 0);
  EXPECT_EQ(run("check " + q(checker_data("F1_ex34_weak_incident.json"))).code, 1);
  const fs::path out = dir / "out/unsewn.json";
  Result r = run("apply --json " + q(checker_data("F5_fig319a_unsew.json")) + " " +
                 q(tools_data("cube.off")) + " -o " + q(out));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["valid"], true);
  EXPECT_EQ(read_map_json_file(out).map.size(), 48u);
  // No match: sew on a closed cube; a scheme option on a concrete rule.
  EXPECT_EQ(run("apply " + q(checker_data("F5_fig319a_sew.json")) + " " +
                q(tools_data("cube.off")) + " -o " + q(dir / "out/x.json"))
                .code,
            1);
  expect_bad_input(
      "apply --all " + q(checker_data("F5_fig319a_sew.json")) + " " + q(tools_data("cube.off")),
      "F5_fig319a_sew.json", "--match");
  EXPECT_EQ(outputs(), 1u);
}

TEST_F(Cli, CheckAndApplyScheme) {
  EXPECT_EQ(run("check " + q(rule_data("quad_subdivision.json"))).code, 0);
  // Quad subdivision of the cube at one hook: the whole component, 48 -> 192 darts.
  const fs::path out = dir / "out/quads.json";
  Result r = run("apply --json " + q(rule_data("quad_subdivision.json")) + " " +
                 q(tools_data("cube.off")) + " --hook 0 -o " + q(out));
  EXPECT_EQ(r.code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["darts"], 192);
  EXPECT_EQ(j["valid"], true);
  ASSERT_EQ(j["tables"].size(), 1u);
  EXPECT_EQ(j["tables"][0]["comatch"]["n3"].size(), 48u);
  EXPECT_EQ(j["tables"][0]["comatch"]["n0"][0], j["tables"][0]["orbit"][0]);
  EXPECT_EQ(read_map_json_file(out).map.size(), 192u);
  // --all: vertex insertion on every edge of the cube (12 applications), then quad subdivision
  // once.
  r = run("apply --json --all " + q(rule_data("vertex_insertion.json")) + " " +
          q(tools_data("cube.off")));
  EXPECT_EQ(r.code, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["darts"], 96);
  EXPECT_EQ(j["valid"], true);
  r = run("apply --all " + q(rule_data("quad_subdivision.json")) + " " + q(tools_data("cube.off")));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("applied 1 time"), std::string::npos) << r.out;
  // Two hooks: sew two free edges of an open square. Its positions clash: the sewn vertices merge
  // orbits of different positions without an expression (E-merge, exit 1, nothing written)...
  r = run("apply " + q(rule_data("sew2.json")) + " " + q(test_data("square.json")) +
          " --hook 0,4 -o " + q(dir / "out/sewn.json"));
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("E-merge"), std::string::npos) << r.out;
  // ... unless the embeddings are dropped.
  r = run("apply --no-embeddings " + q(rule_data("sew2.json")) + " " + q(test_data("square.json")) +
          " --hook 0,4 -o " + q(dir / "out/sewn.json"));
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  // Not applicable (exit 1, the reason, no output): sew on the closed cube.
  r = run("apply " + q(rule_data("sew2.json")) + " " + q(tools_data("cube.off")) +
          " --hook 0,8 -o " + q(dir / "out/x.json"));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.out.find("not applicable, because"), std::string::npos) << r.out;
  r = run("apply " + q(rule_data("sew2.json")) + " " + q(tools_data("cube.off")) +
          " --hook 0,0 -o " + q(dir / "out/x.json"));
  EXPECT_EQ(r.code, 1) << r.err;
  // Bad input (exit 2): unknown dart, wrong number of hooks, --all with two hooks, no hook.
  const std::string quad = q(rule_data("quad_subdivision.json")) + " " + q(tools_data("cube.off"));
  expect_bad_input("apply " + quad + " --hook 999 -o " + q(dir / "out/x.json"), "--hook",
                   "not a dart");
  expect_bad_input("apply " + quad + " --hook 0,1 -o " + q(dir / "out/x.json"), "quad_subdivision",
                   "1 hook(s), 2 dart(s)");
  expect_bad_input(
      "apply " + q(rule_data("sew2.json")) + " " + q(tools_data("cube.off")) + " --all", "--all",
      "one hook");
  expect_bad_input("apply " + quad, "--hook", "--all");
  expect_bad_input("apply " + quad + " --hook 0 --match n0=0", "--match");
  EXPECT_EQ(outputs(), 2u);
}

// Embeddings through `gmr apply` (docs/embeddings.md): Catmull-Clark positions on the cube in OFF,
// OBJ and JSON (the JSON round-trips), a malformed expression located by rule, node and column.
TEST_F(Cli, ApplyCarriesPositions) {
  const fs::path off = dir / "out/cc.off", obj = dir / "out/cc.obj", json = dir / "out/cc.json";
  Result r = run("apply " + q(rule_data("quad_subdivision.json")) + " " +
                 q(tools_data("cube.off")) + " --all -o " + q(off));
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("embeddings: position <1,2>"), std::string::npos) << r.out;
  const EmbeddedMap m = read_off_file(off);
  EXPECT_EQ(count_orbits(m.map, OrbitType{1, 2}), 26u);
  // The corner (0,0,0) of the unit cube moves to (Q + 2R + 0)/3 with Q = (1/3,1/3,1/3) (mean of
  // the face points) and R = (1/6,1/6,1/6) (mean of the edge midpoints).
  bool corner = false;
  for (Dart d : orbit_representatives(m.map, OrbitType{1, 2})) {
    const Vec3 p = m.position().get(d);
    if (std::abs(p[0] - 2.0 / 9) < 1e-12 && std::abs(p[1] - 2.0 / 9) < 1e-12 &&
        std::abs(p[2] - 2.0 / 9) < 1e-12)
      corner = true;
  }
  EXPECT_TRUE(corner);
  EXPECT_EQ(run("apply " + q(rule_data("quad_subdivision.json")) + " " + q(tools_data("cube.off")) +
                " --all -o " + q(obj))
                .code,
            0);
  EXPECT_NE(read_text_file(obj).find("v 0.2222222222222222 0.2222222222222222 0.2222222222222222"),
            std::string::npos);
  EXPECT_EQ(run("apply " + q(rule_data("quad_subdivision.json")) + " " + q(tools_data("cube.off")) +
                " --all -o " + q(json))
                .code,
            0);
  const EmbeddedMap f = read_map_json_file(json);
  ASSERT_NE(f.find("position"), nullptr);
  EXPECT_EQ(write_map_json(read_map_json(write_map_json(f))), write_map_json(f));
  // gmr check reports the static embedding checks (sew with positions and no expression: E-merge).
  r = run("check " + q(source_dir() / "checker/tests/data/embeddings/sew2_positions.json"));
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("E-merge"), std::string::npos) << r.out;
  const fs::path bad = source_dir() / "model/expr/tests/data/bad_expression.json";
  expect_bad_input("apply " + q(bad) + " " + q(tools_data("cube.off")) + " --all",
                   "$.right.nodes[1].expressions[0].code (rule bad_midpoint, node n1), column 1",
                   "affine combination of mass 2");
  EXPECT_EQ(outputs(), 3u);
}

// `gmr fold` (thesis Alg. 6): the cube on <1,2> folds into 8 nodes with the opposite vertex <2,1>;
// the open box on <0,2> is an instantiation failure (exit 1, named in text and JSON); bad orbit
// types and darts are bad input.
TEST_F(Cli, FoldPrintsTheSchemeOrTheNamedFailure) {
  Result r = run("fold " + q(tools_data("cube.off")) + " --orbit '<1,2>' --dart 0");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("8 nodes"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("n7 <2,1>"), std::string::npos) << r.out;
  const fs::path box = source_dir() / "inference/tests/data/open_box.off";
  r = run("fold --json " + q(box) + " --orbit '<0,2>' --dart 1");
  EXPECT_EQ(r.code, 1) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["folded"], false);
  EXPECT_EQ(j["failure"]["kind"], "instantiation failure");
  EXPECT_EQ(j["failure"]["dimension"], 2);
  r = run("fold " + q(tools_data("cube.off")) + " --orbit '<>' --dart 47");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("48 nodes"), std::string::npos) << r.out;
  expect_bad_input("fold " + q(tools_data("cube.off")) + " --orbit '<0,_>' --dart 0", "--orbit",
                   "`_`");
  expect_bad_input("fold " + q(tools_data("cube.off")) + " --orbit '<0,1>' --dart 48", "--dart",
                   "not a dart");
  expect_bad_input("fold " + q(tools_data("cube.off")) + " --orbit '<0,1' --dart 0", "--orbit");
}

// `gmr infer`: the quad subdivision from the cube and its subdivision (identity mapping), written
// as gmr.rule + DOT + SVG + summary and accepted by `gmr check`; the triangle -> hexagon vertex
// split (explicit --map) infers nothing (exit 1) and writes the rejected scheme with its
// diagnostics.
TEST_F(Cli, InferWritesCheckedSchemes) {
  const fs::path cube = dir / "cube.json", sub = dir / "sub.json";
  ASSERT_EQ(run("convert " + q(tools_data("cube.off")) + " " + q(cube)).code, 0);
  ASSERT_EQ(run("apply " + q(rule_data("quad_subdivision.json")) + " " + q(cube) + " --hook 0 -o " +
                q(sub))
                .code,
            0);
  Result r = run("infer " + q(cube) + " " + q(sub) + " --orbit '<0,1,2>' -o " + q(dir / "out/q"));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("1 rule(s) inferred"), std::string::npos) << r.out;
  for (const char* f : {"rule_0.json", "rule_0.dot", "rule_0.svg", "summary.txt"})
    EXPECT_TRUE(fs::exists(dir / "out/q" / f)) << f;
  EXPECT_NE(read_text_file(dir / "out/q/rule_0.svg").find("<svg"), std::string::npos);
  const auto rule = nlohmann::json::parse(read_text_file(dir / "out/q/rule_0.json"));
  EXPECT_EQ(rule["format"], "gmr.rule");
  EXPECT_EQ(rule["left"]["nodes"].size(), 1u);
  EXPECT_EQ(rule["right"]["nodes"].size(), 4u);
  EXPECT_EQ(run("check " + q(dir / "out/q/rule_0.json")).code, 0);
  // Prior-cut loops on a closed surface: nothing to cut, the same rule.
  r = run("infer " + q(cube) + " " + q(sub) + " --orbit '<0,1,2>' --prior-cut-loops 0,1");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("1 rule(s) inferred"), std::string::npos) << r.out;
  // A scheme too large to lay out (<> on 192 + 768 darts: 960 nodes): DOT only, said in the
  // summary.
  const fs::path sub2 = dir / "sub2.json";
  ASSERT_EQ(run("apply " + q(rule_data("quad_subdivision.json")) + " " + q(sub) + " --hook 0 -o " +
                q(sub2))
                .code,
            0);
  r = run("infer " + q(sub) + " " + q(sub2) + " --orbit '<>' -o " + q(dir / "out/e"));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "out/e/rule_0.dot"));
  EXPECT_FALSE(fs::exists(dir / "out/e/rule_0.svg"));
  EXPECT_NE(read_text_file(dir / "out/e/summary.txt").find("rule_0.svg not drawn: 960 nodes"),
            std::string::npos);
  // Every orbit type, JSON: the <0,1,2> rule is among them; duplicates are counted.
  r = run("infer --json --all-orbits " + q(cube) + " " + q(sub));
  EXPECT_EQ(r.code, 0) << r.err;
  const auto all = nlohmann::json::parse(r.out);
  EXPECT_EQ(all["mapping"], "identity");
  EXPECT_GE(all["rules"].size(), 2u);
  EXPECT_EQ(all["attempts"][0]["orbit"], "<>");
  // Triangle -> hexagon, vertex split: folded, rejected by the checker, nothing inferred.
  const fs::path tri = dir / "tri.json", hex = dir / "hex.json";
  std::ofstream(tri) << R"({"format":"gmr.gmap","version":1,"kind":"gmap","dimension":2,"darts":6,
    "alpha":{"0":[1,0,3,2,5,4],"1":[5,2,1,4,3,0],"2":[0,1,2,3,4,5]}})";
  std::ofstream(hex) << R"({"format":"gmr.gmap","version":1,"kind":"gmap","dimension":2,"darts":12,
    "alpha":{"0":[1,0,3,2,5,4,7,6,9,8,11,10],"1":[11,2,1,4,3,6,5,8,7,10,9,0],"2":[0,1,2,3,4,5,6,7,8,9,10,11]}})";
  const fs::path vsplit = source_dir() / "inference/tests/data/triangle_hexagon_vertex_split.json";
  r = run("infer " + q(tri) + " " + q(hex) + " --orbit '<0,1,2>' --map " + q(vsplit) + " -o " +
          q(dir / "out/v"));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.out.find("rejected by the checker"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(dir / "out/v/rejected_0.json"));
  EXPECT_TRUE(fs::exists(dir / "out/v/rejected_0.svg"));
  EXPECT_FALSE(fs::exists(dir / "out/v/rule_0.json"));
  const fs::path esplit = source_dir() / "inference/tests/data/triangle_hexagon_edge_split.json";
  EXPECT_EQ(run("infer " + q(tri) + " " + q(hex) + " --orbit '<0,1,2>' --map " + q(esplit)).code,
            0);
  // Bad input: both orbit options, a mapping pairing one after dart twice.
  expect_bad_input("infer " + q(tri) + " " + q(hex) + " --orbit '<0>' --all-orbits",
                   "--all-orbits");
  expect_bad_input("infer " + q(tri) + " " + q(hex) + " --cut-loops 3", "--cut-loops",
                   "not a dimension");
  expect_bad_input("infer " + q(tri) + " " + q(hex) + " --prior-cut-loops 3", "--prior-cut-loops",
                   "not a dimension");
  expect_bad_input("infer " + q(tri) + " " + q(hex) + " --explicit-loops x", "--explicit-loops");
  // Every relabeling combination, with the loops of preserved nodes cut: still exactly one rule.
  r = run("infer " + q(tri) + " " + q(hex) + " --orbit '<0,1,2>' --map " + q(esplit) +
          " --all-relabelings --cut-loops 2");
  EXPECT_EQ(r.code, 0) << r.err;
  const fs::path bad = dir / "bad_map.json";
  std::ofstream(bad) << R"({"format":"gmr.mapping","version":1,"pairs":[[0,0],[1,0]]})";
  expect_bad_input("infer " + q(tri) + " " + q(hex) + " --map " + q(bad), "pairs[1]",
                   "image of two darts");
}

// `gmr events`: the static table per orbit type (text and gmr.events JSON), every rule of a .jme
// file; `gmr apply --events`: the event log of one application, written atomically.
TEST_F(Cli, EventsPrintsTheStaticTable) {
  const std::string tri = q(tools_data("rules/face_triangulation.json"));
  Result r = run("events " + tri);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("implicit split along 2 of L<0,1>(n0) -> R<0,1>(n0), possible"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("modification of L<1,2>(n0) -> R<1,2>(n0), certain"), std::string::npos)
      << r.out;
  r = run("events " + tri + " --orbits \"<1>,<0,2>\" --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["format"], "gmr.events");
  EXPECT_EQ(j["kind"], "static");
  ASSERT_EQ(j["orbits"].size(), 2u);
  EXPECT_EQ(j["orbits"][0]["orbit"], "<1>");
  EXPECT_EQ(j["orbits"][1]["orbit"], "<0,2>");
  r = run("events " + q(tools_data("jerboa/JerboaTrackingOrbit.jme")) +
          " --orbits \"<0,1>\" --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["kind"], "static-set");
  expect_bad_input("events " + tri + " --orbits \"<0,3>\"", "<0,3>", "not a dimension");
  expect_bad_input("events " + tri + " --orbits \"<0;1>\"", "--orbits");
}

// A map with a JSON embedding (here a label string per face) converts and validates as it is, but a
// rule application refuses it: new orbits would get no value (docs/embeddings.md). Without the
// embeddings (--no-embeddings) it applies.
TEST_F(Cli, ApplyRefusesJsonEmbeddingsThatConvertKeeps) {
  const fs::path cube = dir / "cube.json", labelled = dir / "labelled.json",
                 copy = dir / "out/copy.json";
  ASSERT_EQ(run("convert " + q(tools_data("cube.off")) + " " + q(cube)).code, 0);
  nlohmann::json j = nlohmann::json::parse(read_text_file(cube));
  j["embeddings"].push_back(
      {{"name", "label"}, {"orbit", "<0,1>"}, {"values", {{{"dart", 0}, {"value", "top"}}}}});
  std::ofstream(labelled) << j.dump();
  EXPECT_EQ(run("convert " + q(labelled) + " " + q(copy)).code, 0);
  EXPECT_EQ(nlohmann::json::parse(read_text_file(copy))["embeddings"], j["embeddings"]);
  expect_bad_input("apply " + q(rule_data("quad_subdivision.json")) + " " + q(labelled) + " --all",
                   "embedding 'label', dart 0", "rule applications carry numeric embeddings only");
  EXPECT_EQ(run("apply " + q(rule_data("quad_subdivision.json")) + " " + q(labelled) +
                " --all --no-embeddings")
                .code,
            0);
}

TEST_F(Cli, ApplyWritesTheEventLog) {
  const std::string tri = q(tools_data("rules/face_triangulation.json"));
  const std::string house = q(source_dir() / "checker/events/tests/data/house.json");
  const fs::path log = dir / "out" / "log.json";
  Result r = run("apply " + tri + " " + house + " --hook 0 --events " + q(log));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(read_text_file(log));
  EXPECT_EQ(j["format"], "gmr.events");
  EXPECT_EQ(j["kind"], "log");
  ASSERT_EQ(j["orbits"].size(), 8u);
  EXPECT_EQ(j["orbits"][4]["orbit"], "<0,1>");
  ASSERT_EQ(j["orbits"][4]["events"].size(), 1u);
  EXPECT_EQ(j["orbits"][4]["events"][0]["event"], "split");
  EXPECT_EQ(j["orbits"][4]["events"][0]["status"], "confirmed");
  EXPECT_EQ(j["orbits"][4]["events"][0]["after"].size(), 4u);
  fs::remove(log);
  // Not applicable: unsewing at a 2-free dart does not match, and no log is written.
  r = run("apply " + q(tools_data("rules/unsew2.json")) + " " + house + " --hook 4 --events " +
          q(log));
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  EXPECT_EQ(outputs(), 0u);
  expect_bad_input("apply " + tri + " " + house + " --hook 0 --orbits \"<0,1>\"", "--orbits",
                   "--events");
  expect_bad_input(
      "apply " + tri + " " + house + " --hook 0 --events " + q(log) + " --orbits \"<0,7>\"",
      "<0,7>");
  EXPECT_EQ(outputs(), 0u);
}

// `gmr apply --all --events`: one log per application, in order ("log-set"); --orbits restricts the
// logged orbit types.
TEST_F(Cli, ApplyEverywhereLogsEveryApplication) {
  const std::string tri = q(tools_data("rules/face_triangulation.json"));
  const std::string house = q(source_dir() / "checker/events/tests/data/house.json");
  const fs::path log = dir / "all.json";
  Result r =
      run("apply " + tri + " " + house + " --all --events " + q(log) + " --orbits \"<0,1>,<1,2>\"");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("applied 2 times"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(read_text_file(log));
  EXPECT_EQ(j["format"], "gmr.events");
  EXPECT_EQ(j["kind"], "log-set");
  ASSERT_EQ(j["applications"].size(), 2u);  // the square at dart 0, then the roof at dart 8
  EXPECT_EQ(j["applications"][0]["hooks"], nlohmann::json::array({0}));
  EXPECT_EQ(j["applications"][1]["hooks"], nlohmann::json::array({8}));
  for (const auto& app : j["applications"]) {
    EXPECT_EQ(app["kind"], "log");
    ASSERT_EQ(app["orbits"].size(), 2u);
    EXPECT_EQ(app["orbits"][0]["orbit"], "<0,1>");
    EXPECT_EQ(app["orbits"][1]["orbit"], "<1,2>");
    ASSERT_EQ(app["orbits"][0]["events"].size(), 1u);
    EXPECT_EQ(app["orbits"][0]["events"][0]["event"], "split");
  }
  EXPECT_EQ(j["applications"][0]["orbits"][0]["events"][0]["after"].size(),
            4u);  // square: 4 triangles
  EXPECT_EQ(j["applications"][1]["orbits"][0]["events"][0]["after"].size(), 3u);  // roof: 3
}

// Concrete rules: `gmr events` analyses them as schemes on <> (one dart per node), `gmr apply
// --events` logs their application; the result is the one without --events.
TEST_F(Cli, EventsOfConcreteRules) {
  const std::string unsew = q(source_dir() / "checker/tests/data/F5_fig319a_unsew.json");
  const std::string grid = q(source_dir() / "checker/events/tests/data/quad_grid_2x2.off");
  Result r = run("events " + unsew + " --orbits \"<0,2>\"");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("explicit split of L<0,2>(a) -> R<0,2>(a), R<0,2>(c), certain"),
            std::string::npos)
      << r.out;
  const fs::path log = dir / "log.json", with = dir / "with.json", without = dir / "without.json";
  r = run("apply " + unsew + " " + grid + " --match a=2 --events " + q(log) +
          " --orbits \"<0,2>,<0,1,2>\" -o " + q(with));
  ASSERT_EQ(r.code, 0) << r.err;
  r = run("apply " + unsew + " " + grid + " --match a=2 -o " + q(without));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(read_text_file(with), read_text_file(without));
  const auto j = nlohmann::json::parse(read_text_file(log));
  EXPECT_EQ(j["kind"], "log");
  ASSERT_EQ(j["orbits"].size(), 2u);
  ASSERT_EQ(j["orbits"][0]["events"].size(), 1u);
  EXPECT_EQ(j["orbits"][0]["events"][0]["event"], "split");
  EXPECT_EQ(j["orbits"][0]["events"][0]["status"], "certain");
  EXPECT_EQ(j["orbits"][1]["events"][0]["event"], "modification");  // the grid stays connected
  expect_bad_input("events " + q(source_dir() / "checker/tests/data/omap_face_split.json"),
                   "O-maps");
}

TEST_F(Cli, DotDrawsTheStaticEvents) {
  const std::string tri = q(tools_data("rules/face_triangulation.json"));
  Result r = run("dot " + tri + " --events \"<0,1>\"");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("S2?"), std::string::npos) << r.out;      // possible implicit split
  EXPECT_NE(r.out.find("#ffd58a"), std::string::npos) << r.out;  // drawn as "to confirm"
  r = run("dot " + tri + " --events \"<1,2>\"");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("mod"), std::string::npos) << r.out;  // certain modification
  EXPECT_NE(r.out.find("#ff9c9c"), std::string::npos) << r.out;
  expect_bad_input("dot " + tri + " --events \"<0,5>\"", "<0,5>");
  expect_bad_input("dot " + tri + " --events \"<0,1>\" --check", "--events");
}
