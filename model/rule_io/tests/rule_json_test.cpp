// gmr.rule reading/writing (model/rule_json.hpp), Assumption 4 and the joint representation.
#include "model/rule_io/rule_json.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "model/core/error.hpp"
#include "model/testing/scratch_dir.hpp"

using namespace gmr;
using namespace gmr::graph;
using namespace gmr::rewrite;
using namespace gmr::io;

namespace {

const char* kGood = R"({"format":"gmr.rule","version":1,"kind":"concrete","map":"gmap","n":2,
  "left":{"nodes":["a","b","d"],"arcs":[{"from":"a","to":"b","label":0},{"from":"d","to":"d","label":1}],
          "links":[{"nodes":["a","a"],"label":2}]},
  "right":{"nodes":["a","b","e"],"arcs":[{"from":"a","to":"b","label":0},{"from":"b","to":"a","label":0}]}})";

// Replaces the first occurrence of `from` in kGood by `to` and returns the location of the error.
std::pair<ErrorCode, std::string> error_of(const std::string& text) {
  try {
    parse_rule(text);
  } catch (const Error& e) {
    return {e.code(), e.location()};
  }
  return {ErrorCode::Usage, "no error"};
}

std::string edit(const std::string& from, const std::string& to) {
  std::string s = kGood;
  const auto p = s.find(from);
  EXPECT_NE(p, std::string::npos) << from;
  return s.replace(p, from.size(), to);
}

}  // namespace

TEST(RuleJson, ReadsAndDeducesStatuses) {
  const Rule r = parse_rule(kGood);
  EXPECT_EQ(r.preserved_nodes().size(), 2u);
  ASSERT_EQ(r.deleted_nodes().size(), 1u);
  EXPECT_EQ(r.left().name(r.deleted_nodes()[0]), "d");
  ASSERT_EQ(r.added_nodes().size(), 1u);
  EXPECT_EQ(r.left_arc_status(ArcId(0)),
            ElemStatus::Preserved);  // a-0->b on both sides (Assumption 4)
  EXPECT_EQ(r.left_arc_status(ArcId(1)), ElemStatus::Deleted);
  EXPECT_EQ(r.left_arc_status(ArcId(2)),
            ElemStatus::Deleted);  // the 2-loop (a link on one node = one arc)
  EXPECT_EQ(r.left().num_arcs(), 3u);
  EXPECT_EQ(r.right_arc_status(ArcId(1)), ElemStatus::Added);
}

TEST(RuleJson, RoundTripAndAtomicWrite) {
  const Rule r = parse_rule(kGood);
  const auto dir = gmr::testing::scratch_path("gmr_rule_json_test");
  std::filesystem::create_directories(dir);
  const auto path = dir / "r.json";
  write_rule_file(r, path);
  const Rule back = read_rule_file(path);
  EXPECT_EQ(rule_to_json(back), rule_to_json(r));
  size_t files = 0;
  for (auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
  EXPECT_EQ(files, 1u);  // no temporary left behind
  std::filesystem::remove_all(dir);
  EXPECT_EQ(rule_to_json(r).begin().key(), "format");
}

TEST(RuleJson, LocatedErrors) {
  EXPECT_EQ(error_of(edit("\"label\":1}", "\"label\":3}")),
            std::pair(ErrorCode::Schema, std::string("$.left.arcs[1].label")));
  EXPECT_EQ(error_of(edit("\"to\":\"b\",\"label\":0},{\"from\":\"b\"",
                          "\"to\":\"zz\",\"label\":0},{\"from\":\"b\""))
                .second,
            "$.right.arcs[0].to");
  EXPECT_EQ(error_of(edit("[\"a\",\"b\",\"d\"]", "[\"a\",\"b\",\"a\"]")).second, "$.left.nodes[2]");
  EXPECT_EQ(error_of(edit("[\"a\",\"b\",\"d\"]", "[\"a\",\"\",\"d\"]")).second, "$.left.nodes[1]");
  EXPECT_EQ(error_of(edit("\"concrete\"", "\"scheme\"")).second, "$.kind");
  EXPECT_EQ(error_of(edit("\"gmap\"", "\"cmap\"")).second, "$.map");
  EXPECT_EQ(error_of(edit("\"gmr.rule\"", "\"gmr.gmap\"")).second, "$.format");
  EXPECT_EQ(error_of(edit("\"nodes\":[\"a\",\"a\"]", "\"nodes\":[\"a\"]")).second,
            "$.left.links[0].nodes");
  EXPECT_EQ(error_of(edit("\"left\":{", "\"left\":{\"extra\":1,")).second, "$.left.extra");
  EXPECT_EQ(error_of(edit("\"map\":\"gmap\"", "\"map\":\"omap\"")).second,
            "$.left.arcs[0].label");  // 0 not in 1..2
  EXPECT_EQ(error_of("{\"format\": ").first, ErrorCode::Parse);
  EXPECT_EQ(error_of("[1,2]").first, ErrorCode::Schema);
}

TEST(RuleJson, ProgrammaticRuleValidation) {
  DGraph L, R;
  L.add_node("a");
  L.add_node("a");
  EXPECT_THROW(Rule(L, R, 2), Error);
  DGraph L2;
  L2.add_node("a");
  L2.add_arc(Node(0), Node(0), 7);
  try {
    Rule(L2, R, 2);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Schema);
    EXPECT_EQ(e.location(), "left.arcs[0]");
  }
}

TEST(RuleJson, JointRepresentationRoundTrip) {
  const Rule r = parse_rule(kGood);
  const JointRepresentation j = to_joint(r);
  EXPECT_EQ(j.graph.num_nodes(), r.left().num_nodes() + r.right().num_nodes());
  EXPECT_EQ(j.graph.num_arcs(),
            r.left().num_arcs() + r.right().num_arcs() + r.preserved_nodes().size());
  EXPECT_EQ(rule_to_json(from_joint(j)), rule_to_json(r));
  JointRepresentation bad = j;
  bad.graph.add_arc(Node(0), Node(static_cast<uint32_t>(r.left().num_nodes())),
                    0);  // crosses the sides
  EXPECT_THROW(from_joint(bad), Error);
}
