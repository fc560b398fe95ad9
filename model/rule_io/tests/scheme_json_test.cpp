// gmr.rule files of kind "scheme": round trips, atomic writing, located errors.
#include "model/rule_io/scheme_json.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "model/core/error.hpp"
#include "model/scheme/tests/scheme_fixtures.hpp"
#include "model/testing/scratch_dir.hpp"

using namespace gmr;
using namespace gmr::scheme;
using namespace gmr::io;
using namespace gmr::fixtures;

namespace {

std::string error_location(const std::string& text) {
  try {
    parse_scheme(text, "t.json");
  } catch (const Error& e) {
    return e.location() + " | " + e.message();
  }
  return "no error";
}

const char* kQuad = R"json({
  "format": "gmr.rule", "version": 1, "kind": "scheme", "name": "q", "map": "gmap", "n": 2,
  "orbit": "<0,1,2>", "hooks": ["n0"],
  "embeddings": [{"name": "pos", "orbit": "<1,2>", "type": "point"}],
  "left": {"nodes": [{"name": "n0", "orbit": "<0,1,2>"}], "arcs": []},
  "right": {"nodes": [{"name": "n0", "orbit": "<_,1,2>"},
                      {"name": "n1", "orbit": "<_,_,2>", "expressions": [{"embedding": "pos", "code": "middle(<0>_pos(n0))"}]}],
            "arcs": [{"nodes": ["n0", "n1"], "label": 0}]}
})json";

}  // namespace

TEST(SchemeJson, RoundTrip) {
  for (const RuleScheme& r : {quad_subdivision(), vertex_insertion(), sew2()}) {
    const std::string text = scheme_to_json_text(r);
    RuleScheme back = parse_scheme(text);
    EXPECT_EQ(back, r) << text;
    EXPECT_EQ(scheme_to_json_text(back), text);
  }
  RuleScheme q = parse_scheme(kQuad);
  ASSERT_EQ(q.right.nodes[1].expressions.size(), 1u);
  EXPECT_EQ(q.right.nodes[1].expressions[0].code, "middle(<0>_pos(n0))");
  q.precondition = "return true;";
  q.description = "with \"quotes\"";
  EXPECT_EQ(parse_scheme(scheme_to_json_text(q)), q);
  EXPECT_EQ(rule_document_kind(nlohmann::json::parse(kQuad)), "scheme");
}

TEST(SchemeJson, AtomicFile) {
  const auto dir = gmr::testing::scratch_path("gmr_scheme_json_test");
  std::filesystem::create_directories(dir);
  const auto path = dir / "quad.json";
  write_scheme_file(quad_subdivision(), path);
  EXPECT_EQ(read_scheme_file(path), quad_subdivision());
  // No temporary file left behind.
  size_t files = 0;
  for ([[maybe_unused]] auto& e : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1u);
  EXPECT_THROW(read_scheme_file(dir / "missing.json"), Error);
  std::filesystem::remove_all(dir);
}

TEST(SchemeJson, LocatedErrors) {
  auto with = [](const std::string& from, const std::string& to) {
    std::string s = kQuad;
    const size_t p = s.find(from);
    EXPECT_NE(p, std::string::npos) << from;
    return s.replace(p, from.size(), to);
  };
  EXPECT_EQ(error_location(with("\"n1\", \"orbit\": \"<_,_,2>\"", "\"n1\", \"orbit\": \"<_,2>\""))
                .substr(0, 32),
            "t.json:$.right.nodes[1].orbit | ");
  EXPECT_NE(
      error_location(with("[\"n0\", \"n1\"]", "[\"n0\", \"zz\"]")).find("$.right.arcs[0].nodes[1]"),
      std::string::npos);
  EXPECT_NE(error_location(with("\"hooks\": [\"n0\"]", "\"hooks\": [\"n1\"]")).find("$.hooks[0]"),
            std::string::npos);
  EXPECT_NE(error_location(with("\"label\": 0", "\"label\": 3")).find("$.right.arcs[0].label"),
            std::string::npos);
  EXPECT_NE(
      error_location(with("\"<0,1,2>\", \"hooks\"", "\"<0,_,2>\", \"hooks\"")).find("$.orbit"),
      std::string::npos);
  EXPECT_NE(error_location(with("\"kind\": \"scheme\"", "\"kind\": \"concrete\"")).find("$.kind"),
            std::string::npos);
  EXPECT_NE(error_location(with("\"map\": \"gmap\"", "\"map\": \"omap\"")).find("$.map"),
            std::string::npos);
  EXPECT_NE(error_location(with("\"n\": 2", "\"n\": 2, \"extra\": 1")).find("extra"),
            std::string::npos);
  EXPECT_NE(error_location(with("{\"name\": \"n0\", \"orbit\": \"<_,1,2>\"}",
                                "{\"name\": \"n1\", \"orbit\": \"<_,1,2>\"}"))
                .find("$.right.nodes[1].name"),
            std::string::npos);
  EXPECT_NE(error_location(with("\"orbit\": \"<_,1,2>\"", "\"orbit\": \"<_,1,\""))
                .find("$.right.nodes[0].orbit"),
            std::string::npos);
  EXPECT_NE(error_location("{\"format\": \"gmr.rule\",").find("t.json:1:"), std::string::npos);
}
