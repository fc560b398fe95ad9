// Checker diagnostics overlaid on rule diagrams (checker/dot_overlay.hpp): the offending nodes of a
// rejected rule are filled and labelled with the diagnostic code; an accepted rule has none.
#include "checker/dot_overlay.hpp"

#include <gtest/gtest.h>

#include "checker/rule_check.hpp"
#include "model/rule_io/rule_json.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "model/testing/source_tree.hpp"

using namespace gmr;
using namespace gmr::rewrite;
using namespace gmr::scheme;
using namespace gmr::io;
using namespace gmr::draw;
using namespace gmr::checker;

namespace {
std::string source(const std::string& rel) { return gmr::testing::source_path(rel); }

// The line of `dot` from the first occurrence of `start` to its end; empty when there is none.
std::string line_from(const std::string& dot, const std::string& start) {
  const size_t at = dot.find(start);
  return at == std::string::npos ? "" : dot.substr(at, dot.find('\n', at) - at);
}
}  // namespace

TEST(DotOverlay, RejectedConcreteRuleHighlightsTheAddedNode) {
  // Ex. 34: the added node d has no 1-arc (w-I_r(1) fails).
  const Rule r = read_rule_file(source("checker/tests/data/F1_ex34_weak_incident.json"));
  const CheckReport rep = check_rule(r);
  ASSERT_FALSE(rep.ok());
  RuleDotOptions opt;
  opt.highlights = dot_highlights(rep);
  ASSERT_FALSE(opt.highlights.empty());
  const std::string dot = to_dot(r, opt);
  const std::string line = line_from(dot, "R3 [label=\"d\"");
  ASSERT_FALSE(line.empty()) << dot;
  EXPECT_NE(line.find("fillcolor=\"#ff9c9c\""), std::string::npos) << line;
  EXPECT_NE(line.find("I-added-node"), std::string::npos) << line;
  EXPECT_NE(line.find("filled"), std::string::npos) << line;
}

TEST(DotOverlay, SchemeDiagnostics) {
  RuleScheme s = read_scheme_file(source("tools/data/rules/quad_subdivision.json"));
  EXPECT_TRUE(dot_highlights(check_scheme(s)).empty());
  // Drop the 1-arc of the added node n2: it breaks incident arcs I_S(1) at n1 and n2.
  s.right.arcs.erase(s.right.arcs.begin() + 1);
  const CheckReport rep = check_scheme(s);
  ASSERT_FALSE(rep.ok());
  RuleDotOptions opt;
  opt.highlights = dot_highlights(rep);
  const std::string dot = to_dot(s, opt);
  const std::string line = line_from(dot, "R2 [label=\"n2 <2,_,_>\"");
  ASSERT_FALSE(line.empty()) << dot;
  EXPECT_NE(line.find("I-added-node"), std::string::npos) << line;
  EXPECT_NE(line.find("#ff9c9c"), std::string::npos) << line;
}
