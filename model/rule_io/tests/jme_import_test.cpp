// Import of Jerboa .jme rule files: the real 50-rule fixture and located errors.
#include "model/rule_io/jme_import.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <set>

#include "model/core/error.hpp"
#include "model/rule_io/jme_expression.hpp"
#include "model/scheme/scheme_engine.hpp"
#include "model/testing/source_tree.hpp"

using namespace gmr;
using namespace gmr::scheme;
using namespace gmr::io;

namespace {
std::string fixture() {
  return gmr::testing::source_path("tools/data/jerboa/JerboaTrackingOrbit.jme");
}
}  // namespace

TEST(Jme, OrbitAttribute) {
  EXPECT_EQ(parse_jme_orbit("-1,2,3").str(), "<_,2,3>");
  EXPECT_EQ(parse_jme_orbit("").str(), "<>");
  EXPECT_EQ(parse_jme_orbit("0").str(), "<0>");
  EXPECT_THROW(parse_jme_orbit("0,,1"), Error);
  EXPECT_THROW(parse_jme_orbit("-2"), Error);
  EXPECT_THROW(parse_jme_orbit("a"), Error);
}

TEST(Jme, AllFiftyRulesOfTheFixtureImport) {
  JmeModeler m = read_jme_file(fixture());
  EXPECT_EQ(m.name, "RawDynaOrTrackModeler");
  EXPECT_EQ(m.dimension, 3);
  ASSERT_EQ(m.embeddings.size(), 2u);
  EXPECT_EQ(m.embeddings[0].orbit.str(), "<1,2,3>");
  ASSERT_EQ(m.rules.size(), 50u);
  std::set<std::string> names;
  size_t hooks = 0, exprs = 0, arcs = 0, nodes = 0;
  for (const auto& r : m.rules) {
    names.insert(r.name);
    hooks += r.hooks.size();
    nodes += r.left.size() + r.right.size();
    arcs += r.left.arcs.size() + r.right.arcs.size();
    for (const auto& n : r.right.nodes) exprs += n.expressions.size();
  }
  EXPECT_EQ(names.size(), 50u);
  EXPECT_EQ(hooks, 49u);   // kind="HOOK" occurrences
  EXPECT_EQ(nodes, 367u);  // <node> occurrences
  EXPECT_EQ(arcs, 631u);   // <arc> + <arcloop>
  EXPECT_EQ(exprs, 46u);   // <expr> occurrences
  // Spot checks.
  const RuleScheme* sq = nullptr;
  for (const auto& r : m.rules)
    if (r.name == "SubdivQuad") sq = &r;
  ASSERT_NE(sq, nullptr);
  EXPECT_EQ(sq->hooks.size(), 1u);
  const RuleScheme& merge = m.rules[0];
  EXPECT_EQ(merge.name, "MergeEdge");
  EXPECT_EQ(merge.orbit.str(), "<2,3>");
  EXPECT_EQ(merge.left.size(), 4u);
  EXPECT_EQ(merge.right.size(), 2u);
  const RuleScheme& iv = m.rules[1];
  ASSERT_EQ(iv.right.nodes[2].expressions.size(), 1u);
  EXPECT_EQ(iv.right.nodes[2].expressions[0].embedding, "pos");
  EXPECT_EQ(iv.right.nodes[2].expressions[0].jerboa, "return Vec3.mid(n0.pos, n1.pos);");
  EXPECT_EQ(iv.right.nodes[2].expressions[0].code, "middle(n0.pos, n1.pos)");
  const RuleScheme& sew = m.rules[2];
  EXPECT_EQ(sew.name, "SewA2");
  EXPECT_EQ(sew.hooks, (std::vector<std::string>{"n0", "n1"}));
  EXPECT_TRUE(sew.left.arcs[0].is_loop());
}

TEST(Jme, LocatedSchemaErrors) {
  auto loc = [](const std::string& t) {
    try {
      parse_jme(t, "m.jme");
    } catch (const Error& e) {
      return e.location() + " " + e.message();
    }
    return std::string("no error");
  };
  const std::string head =
      "<jerboamodelereditor>\n<modeler name='M' dimension='2'>\n<rules>\n<rule name='r'>\n";
  const std::string left =
      "<left><nodes><node name='n0' orbit='0,1' kind='HOOK'/></nodes><arcs></arcs></left>\n";
  const std::string tail = "</rule>\n</rules>\n</modeler>\n</jerboamodelereditor>\n";
  EXPECT_EQ(loc(head + left + "<right><nodes/><arcs/></right>\n" + tail), "no error");
  EXPECT_NE(loc(head + left +
                "<right><nodes/><arcs>\n<arc dim='0' a='n0' b='zz'/></arcs></right>\n" + tail)
                .find("m.jme:7 arc names unknown node \"n0\""),
            std::string::npos);
  EXPECT_NE(loc(head + left +
                "<right><nodes/><arcs>\n<arcloop dim='x' node='n0'/></arcs></right>\n" + tail)
                .find("m.jme:7"),
            std::string::npos);
  EXPECT_NE(loc(head + "<left><nodes>\n<node name='n0' orbit='0,q'/></nodes></left><right/>" + tail)
                .find("m.jme:6"),
            std::string::npos);
  EXPECT_NE(loc("<jerboamodelereditor><modeler dimension='2'><rules>\n<rule name='r'><left></rule>")
                .find("m.jme:2"),
            std::string::npos);
  EXPECT_NE(loc("<x/>").find("not a Jerboa"), std::string::npos);
  // Malformed XML is located too (model/rule_io/xml.hpp lists the cases).
  EXPECT_EQ(loc(head + left +
                "<right><nodes/><arcs>\n<arc dim='0' a='n0' b='&zz;'/></arcs></right>\n" + tail),
            "m.jme:7 malformed XML: unknown entity &zz; in attribute b");
}

TEST(Jme, DeepNestingIsALocatedError) {
  std::string t =
      "<jerboamodelereditor>\n<modeler name='M' dimension='2'>\n<rules>\n<rule "
      "name='r'>\n<comment>";
  for (int i = 0; i < 20000; ++i) t += "<x>";
  for (int i = 0; i < 20000; ++i) t += "</x>";
  t += "</comment>\n</rule>\n</rules>\n</modeler>\n</jerboamodelereditor>\n";
  try {
    parse_jme(t, "deep.jme");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Parse);
    EXPECT_EQ(e.location(), "deep.jme:5");
    EXPECT_NE(e.message().find("nested too deeply"), std::string::npos) << e.message();
  }
}

// Jerboa expressions of the fixture translated into gmr's language (jme_expression.hpp): every
// translation checks in its rule, the others name why they are not translated.
TEST(Jme, ExpressionsTranslateOrSayWhyNot) {
  const JmeModeler m = read_jme_file(fixture());
  size_t translated = 0, unsupported = 0;
  for (const auto& r : m.rules) {
    ASSERT_EQ(r.embeddings.size(), 2u);
    EXPECT_EQ(r.embeddings[0].type, "point");
    EXPECT_EQ(r.embeddings[1].type, "colour");
    for (const auto& n : r.right.nodes)
      for (const auto& x : n.expressions) {
        EXPECT_FALSE(x.jerboa.empty());
        if (x.code.empty()) {
          ++unsupported;
          EXPECT_FALSE(x.unsupported.empty()) << r.name << " " << n.name;
        } else {
          ++translated;
        }
      }
  }
  EXPECT_EQ(translated + unsupported, 46u);
  EXPECT_GE(translated, 40u);
  std::cout << "[ jme      ] " << translated << " of 46 expressions translated, " << unsupported
            << " unsupported\n";
}

TEST(Jme, TranslationOfTheJerboaForms) {
  auto code = [](const std::string& java) {
    return translate_jerboa_expression(java).code.value_or("<none>");
  };
  EXPECT_EQ(code("return Vec3.mid(n0.pos, n1.pos);"), "middle(n0.pos, n1.pos)");
  EXPECT_EQ(code("return new Vec3(0.5, 1.5,0);"), "point(0.5, 1.5, 0)");
  EXPECT_EQ(code("Vec3 res = new Vec3();\nres.barycenter(<0,1>_pos(n0));\nreturn res.addn(0,0,1);"),
            "((middle(<0,1>_pos(n0))) + vector(0, 0, 1))");
  EXPECT_EQ(code("return n0@1@0.pos.addn(1,0,0);"), "(n0@1@0.pos + vector(1, 0, 0))");
  EXPECT_EQ(code("Color col = new Color(20,20,25);\nreturn col;"),
            "(colour(20 / 255, 20 / 255, 25 / 255))");
  const auto w = translate_jerboa_expression(
      "return new Vec3(Vec3.segmentABByWeight(n0.pos, n0@0.pos, weight));");
  EXPECT_FALSE(w.code);
  EXPECT_EQ(w.unsupported, "Vec3.segmentABByWeight");
}
