// The static pass on the library rules (Gaide et al. 2023, §3): pattern orbits, completeness and
// the pattern events of face triangulation (the rule of Table 1, all 8 orbit types), 2-unsewing,
// 2-sewing, edge deletion and edge collapse.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "checker/events/tests/events_fixtures.hpp"
#include "model/core/error.hpp"

using namespace gmr;
using namespace gmr::events;
using namespace gmr::events::testing;

namespace {

// The pattern events of one orbit type as sorted words: "C", "D", "NM", "M", "S+", "Si2?" (implicit
// split along the 1-based position 2, possible), "M+" / "Mi1" for merges; '?' marks possible.
std::vector<std::string> summary(const OrbitTypeEvents& t) {
  std::vector<std::string> out;
  for (const auto& e : t.events) {
    std::string w;
    switch (e.kind) {
      case PatternEventKind::Creation:
        w = "C";
        break;
      case PatternEventKind::Deletion:
        w = "D";
        break;
      case PatternEventKind::NonModification:
        w = "NM";
        break;
      case PatternEventKind::Modification:
        w = "M";
        break;
      case PatternEventKind::ExplicitSplit:
        w = "S+";
        break;
      case PatternEventKind::ExplicitMerge:
        w = "M+";
        break;
      case PatternEventKind::ImplicitSplit:
        w = "Si";
        break;
      case PatternEventKind::ImplicitMerge:
        w = "Mi";
        break;
    }
    for (uint32_t k : e.positions) w += std::to_string(k + 1);
    if (e.certainty == Certainty::Possible) w += "?";
    out.push_back(w);
  }
  std::sort(out.begin(), out.end());
  return out;
}

using Table = std::map<std::string, std::vector<std::string>>;

void expect_table(const scheme::RuleScheme& s, const Table& want) {
  const StaticEvents st = analyse(s);
  ASSERT_EQ(st.orbits.size(), 8u);
  for (const auto& t : st.orbits) {
    auto w = want.at(t.orbit.str());
    std::sort(w.begin(), w.end());
    EXPECT_EQ(summary(t), w) << s.name << " " << t.orbit.str();
  }
}

bool left_complete(const scheme::RuleScheme& s, const std::string& o, const std::string& node) {
  const StaticEvents st = analyse(s, {OrbitType::parse(o)});
  const auto& l = st.orbits[0].left;
  return l.complete[l.class_of[*s.left.find(node)]];
}

}  // namespace

TEST(StaticEvents, AllOrbitTypesOfDimension2) {
  std::vector<std::string> names;
  for (const auto& o : all_orbit_types(2)) names.push_back(o.str());
  EXPECT_EQ(names, (std::vector<std::string>{"<>", "<0>", "<1>", "<2>", "<0,1>", "<0,2>", "<1,2>",
                                             "<0,1,2>"}));
  EXPECT_EQ(all_orbit_types(3).size(), 16u);
}

// §2.2: R<0,2>(n0) = {n0} is incomplete (no 2), R<0,2>(n1) = {n1, n2} is complete.
TEST(StaticEvents, PatternOrbitsOfTriangulation) {
  const auto s = library_rule("face_triangulation");
  const PatternOrbits r = pattern_orbits(s.right, Side::R, OrbitType{0, 2}.mask());
  const uint32_t n0 = *s.right.find("n0"), n1 = *s.right.find("n1"), n2 = *s.right.find("n2");
  EXPECT_NE(r.class_of[n0], r.class_of[n1]);
  EXPECT_EQ(r.class_of[n1], r.class_of[n2]);
  EXPECT_FALSE(r.complete[r.class_of[n0]]);
  EXPECT_TRUE(r.complete[r.class_of[n1]]);
}

// The pattern level of Table 1 (face triangulation): the implicit splits along n0's second
// position are possible, not static as the paper has it.
TEST(StaticEvents, F1FaceTriangulation) {
  const auto s = library_rule("face_triangulation");
  expect_table(s, {{"<>", {"NM", "C", "C"}},
                   {"<0>", {"NM", "C"}},
                   {"<1>", {"Si2?", "C"}},
                   {"<2>", {"NM", "C", "C"}},
                   {"<0,1>", {"Si2?"}},
                   {"<0,2>", {"NM", "C"}},
                   {"<1,2>", {"M", "C"}},
                   {"<0,1,2>", {"M"}}});
  for (const char* o : {"<>", "<0>", "<1>", "<0,1>"}) EXPECT_TRUE(left_complete(s, o, "n0")) << o;
  for (const char* o : {"<2>", "<0,2>", "<1,2>", "<0,1,2>"})
    EXPECT_FALSE(left_complete(s, o, "n0")) << o;
}

// Fig. 6: the explicit split of 2-unsewing is certain on <2>, <0,2> (complete R pattern orbits) and
// to confirm on <1,2>, <0,1,2>.
TEST(StaticEvents, F2Unsew) {
  expect_table(library_rule("unsew2"), {{"<>", {"NM", "NM"}},
                                        {"<0>", {"NM", "NM"}},
                                        {"<1>", {"NM", "NM"}},
                                        {"<2>", {"S+"}},
                                        {"<0,1>", {"NM", "NM"}},
                                        {"<0,2>", {"S+"}},
                                        {"<1,2>", {"S+?"}},
                                        {"<0,1,2>", {"S+?"}}});
}

TEST(StaticEvents, F3Sew) {
  expect_table(library_rule("sew2"), {{"<>", {"NM", "NM"}},
                                      {"<0>", {"NM", "NM"}},
                                      {"<1>", {"NM", "NM"}},
                                      {"<2>", {"M+"}},
                                      {"<0,1>", {"NM", "NM"}},
                                      {"<0,2>", {"M+"}},
                                      {"<1,2>", {"M+?"}},
                                      {"<0,1,2>", {"M+?"}}});
}

// Fig. 9: n0 deleted; the merge of <1> along position 2 is complete but still to confirm (the
// border edge refutes it); <0,1> is a possible merge and a possible split (an isthmus edge).
TEST(StaticEvents, F4EdgeDeletion) {
  const auto s = library_rule("edge_deletion");
  expect_table(s, {{"<>", {"D", "NM"}},
                   {"<0>", {"D", "NM"}},
                   {"<1>", {"Mi2?"}},
                   {"<2>", {"D", "NM"}},
                   {"<0,1>", {"Mi2?", "Si1?"}},
                   {"<0,2>", {"D", "NM"}},
                   {"<1,2>", {"M"}},
                   {"<0,1,2>", {"Si1?"}}});
  EXPECT_TRUE(left_complete(s, "<1>", "n0"));
  EXPECT_FALSE(left_complete(s, "<0,1>", "n0"));
}

// Figs. 10-11: edge collapse merges and splits <1,2> (both possible).
TEST(StaticEvents, F5EdgeCollapse) {
  expect_table(library_rule("edge_collapse"), {{"<>", {"D", "NM"}},
                                               {"<0>", {"D", "NM"}},
                                               {"<1>", {"Mi1?"}},
                                               {"<2>", {"D", "NM"}},
                                               {"<0,1>", {"M"}},
                                               {"<0,2>", {"D", "NM"}},
                                               {"<1,2>", {"Mi1?", "Si2?"}},
                                               {"<0,1,2>", {"Si2?"}}});
}

TEST(StaticEvents, OrbitTypesAreChecked) {
  const auto s = library_rule("unsew2");
  EXPECT_THROW(analyse(s, {OrbitType{0, 3}}), Error);
  EXPECT_THROW(analyse(s, {OrbitType{0, OrbitType::kHole}}), Error);
}
