// Static embedding checks of rule schemes (checker/embedding_check.hpp): the four subdivision
// schemes with positions are accepted; the counter-examples of thesis Ch. 5 (two terms in one
// orbit class, an added orbit without value, merged orbits without expression) and a type error
// are rejected with their codes and nodes; untranslated Jerboa expressions are warnings.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "checker/scheme_checker.hpp"
#include "model/rule_io/jme_import.hpp"
#include "model/rule_io/scheme_json.hpp"

using namespace gmr;
using namespace gmr::checker;

namespace {

std::filesystem::path root() {
  const char* s = std::getenv("GMR_SOURCE_DIR");
  return std::filesystem::path(s ? s : ".");
}

CheckReport check_file(const std::filesystem::path& p) {
  return check_scheme(io::read_scheme_file(p));
}

const Diagnostic* find(const CheckReport& r, const std::string& code) {
  for (const auto& d : r.diagnostics)
    if (d.code == code) return &d;
  return nullptr;
}

}  // namespace

TEST(EmbeddingCheck, SubdivisionSchemesAreAccepted) {
  for (const char* f : {"quad_subdivision", "loop_subdivision", "sqrt3_subdivision",
                        "doo_sabin_subdivision", "vertex_insertion", "face_triangulation"}) {
    const CheckReport r = check_file(root() / "tools/data/rules" / (std::string(f) + ".json"));
    EXPECT_TRUE(r.holds("embeddings")) << f;
    EXPECT_TRUE(r.ok()) << f;
  }
}

TEST(EmbeddingCheck, TwoTermsInOneClass) {
  const CheckReport r =
      check_file(root() / "checker/tests/data/embeddings/edge_point_two_terms.json");
  EXPECT_FALSE(r.holds("embeddings"));
  const Diagnostic* d = find(r, "E-orbit-terms");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->nodes, (std::vector<std::string>{"n1", "n2"}));
}

TEST(EmbeddingCheck, AddedOrbitWithoutValue) {
  const CheckReport r =
      check_file(root() / "checker/tests/data/embeddings/face_point_without_value.json");
  const Diagnostic* d = find(r, "E-no-value");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->nodes, (std::vector<std::string>{"n3"}));
  EXPECT_EQ(r.count("E-no-value"), 1u);
}

TEST(EmbeddingCheck, MergedOrbitsWithoutExpression) {
  const CheckReport r = check_file(root() / "checker/tests/data/embeddings/sew2_positions.json");
  const Diagnostic* d = find(r, "E-merge");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->nodes, (std::vector<std::string>{"n0", "n1"}));
  // The topology alone is fine.
  EXPECT_TRUE(r.holds("I(2)"));
}

TEST(EmbeddingCheck, TypeErrorsNameTheColumn) {
  const auto s = io::parse_scheme(
      R"json({"format": "gmr.rule", "version": 1, "kind": "scheme", "name": "t", "map": "gmap", "n": 2,
              "orbit": "<0,2>", "hooks": ["n0"], "embeddings": [{"name": "position", "orbit": "<1,2>", "type": "point"}],
              "left": {"nodes": [{"name": "n0", "orbit": "<0,2>"}], "arcs": []},
              "right": {"nodes": [{"name": "n0", "orbit": "<_,2>"}, {"name": "n1", "orbit": "<1,2>"}],
                        "arcs": [{"nodes": ["n0", "n1"], "label": 0}]}})json");
  scheme::RuleScheme bad = s;
  bad.right.nodes[1].expressions.push_back({"position", "n0.position + n0@0.position", {}, {}});
  const CheckReport r = check_scheme(bad);
  const Diagnostic* d = find(r, "E-expression");
  ASSERT_NE(d, nullptr);
  EXPECT_NE(d->message.find("column 1: the expression is an affine combination of mass 2"),
            std::string::npos)
      << d->message;
  // Without expression the added vertex has no value.
  EXPECT_NE(find(check_scheme(s), "E-no-value"), nullptr);
  // Two expressions on one node.
  scheme::RuleScheme twice = s;
  twice.right.nodes[1].expressions = {{"position", "middle(<0>_position(n0))", {}, {}},
                                      {"position", "n0.position", {}, {}}};
  EXPECT_NE(find(check_scheme(twice), "E-unique"), nullptr);
}

TEST(EmbeddingCheck, UntranslatedJerboaExpressionsAreWarnings) {
  const io::JmeModeler m = io::read_jme_file(root() / "tools/data/jerboa/JerboaTrackingOrbit.jme");
  size_t unsupported = 0, type_errors = 0;
  for (const auto& s : m.rules) {
    const CheckReport r = check_scheme(s);
    unsupported += r.count("E-unsupported");
    type_errors += r.count("E-expression");
  }
  EXPECT_EQ(unsupported, 3u);
  EXPECT_EQ(type_errors, 0u);
}
