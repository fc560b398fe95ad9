// The expression language (docs/embeddings.md): parsing with located errors, type checking
// (affine masses, colours, multisets), evaluation on a map (collects keep one value per orbit,
// thesis §5.5.2), propagation through scheme applications (thesis §6.3.4) and its reported
// problems, the gmr.rule reader's located expression errors.
#include <gtest/gtest.h>

#include <cstdlib>

#include "model/core/error.hpp"
#include "model/core/orbit.hpp"
#include "model/core/validity.hpp"
#include "model/expr/compiled_scheme.hpp"
#include "model/expr/evaluator.hpp"
#include "model/expr/parser.hpp"
#include "model/expr/propagation.hpp"
#include "model/map_io/off.hpp"
#include "model/rule_io/scheme_json.hpp"

using namespace gmr;
using namespace gmr::expr;

namespace {

std::string source(const std::string& rel) {
  const char* s = std::getenv("GMR_SOURCE_DIR");
  return std::string(s ? s : ".") + "/" + rel;
}

CheckContext context() {
  CheckContext c;
  c.dimension = 2;
  c.nodes = {"n0", "n1"};
  c.right_only = {"n2"};
  c.embeddings = {{"position", OrbitType{1, 2}, ValueType::Point},
                  {"normal", OrbitType{1, 2}, ValueType::Vector},
                  {"colour", OrbitType{0, 1}, ValueType::Colour},
                  {"weight", OrbitType{}, ValueType::Scalar}};
  c.where = "test";
  return c;
}

// The error of checking `code` as a `t` value: its location and message.
std::pair<std::string, std::string> error_of(const std::string& code, ValueType t) {
  try {
    auto e = parse_expression(code, "test");
    check_expression(*e, context(), t);
  } catch (const Error& err) {
    return {err.location(), err.message()};
  }
  return {"", "no error"};
}

StaticType type_of(const std::string& code, ValueType t) {
  auto e = parse_expression(code, "test");
  return check_expression(*e, context(), t);
}

}  // namespace

TEST(ExpressionParser, RoundTripsThroughText) {
  for (const char* code :
       {"n0.position", "n0@1@0.position", "middle(<0,1>_position(n0))", "<>_position(n0)",
        "(n0.position + n0@0.position) / 2", "0.25 * n0.position + 0.75 * n1.position",
        "-n0.normal", "[middle(<0,1>_position(f)) | f in <1,2>/<0,1>(n0)]", "let k = 3 in k * k",
        "[x.position | x, k in (@0@1)*(n0)]", "colour(1, 0.5, 0)"}) {
    auto e = parse_expression(code);
    const std::string text = to_text(*e);
    EXPECT_EQ(to_text(*parse_expression(text)), text) << code;
  }
  EXPECT_EQ(to_text(*parse_expression("a.p - (b.p - c.p)")), "a.p - (b.p - c.p)");
  EXPECT_EQ(to_text(*parse_expression("(a.p - b.p) - c.p")), "a.p - b.p - c.p");
}

TEST(ExpressionParser, ErrorsNameTheColumn) {
  auto loc = [](const std::string& code) {
    try {
      parse_expression(code, "rule r, R node n1, embedding position");
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::Parse);
      return e.location();
    }
    return std::string("no error");
  };
  EXPECT_EQ(loc("n0.position +"), "rule r, R node n1, embedding position, column 14");
  EXPECT_EQ(loc("middle(<0,1>_position(n0)"), "rule r, R node n1, embedding position, column 26");
  EXPECT_EQ(loc("<0,0>_position(n0)"), "rule r, R node n1, embedding position, column 1");
  EXPECT_EQ(loc("n0.position $"), "rule r, R node n1, embedding position, column 13");
  EXPECT_EQ(loc(""), "rule r, R node n1, embedding position, column 1");
  EXPECT_EQ(loc("[n0.position | x on <0>/<1>(n0)]"),
            "rule r, R node n1, embedding position, column 18");
}

TEST(ExpressionParser, HostileInputStaysWithinTheLimits) {
  // Deep parentheses and unary chains: refused at the nesting limit, not a stack overflow.
  const std::string deep = std::string(2000, '(') + "1" + std::string(2000, ')');
  try {
    parse_expression(deep, "deep");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(e.message().find("nesting deeper than 100"), std::string::npos) << e.message();
  }
  EXPECT_THROW(parse_expression(std::string(5000, '-') + "1"), Error);
  // Long operator chains (a left-nested tree as deep as the chain) are bounded by the length.
  std::string chain = "1";
  while (chain.size() + 2 <= kMaxExpressionLength) chain += "+1";
  EXPECT_NO_THROW(parse_expression(chain));
  try {
    parse_expression(chain + "+1+1");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(e.message().find("longer than 4096"), std::string::npos) << e.message();
  }
  const std::string nested = std::string(kMaxExpressionNesting - 1, '(') + "1" +
                             std::string(kMaxExpressionNesting - 1, ')');
  EXPECT_NO_THROW(parse_expression(nested));
  // A dimension far out of range in an orbit type (found by the fuzzer: a shift by 99999999).
  EXPECT_THROW(parse_expression("<0,99999999>_position(n0)"), Error);
  EXPECT_THROW(parse_expression("[n0.position | x in <1,2>/<0,2147483647>(n0)]"), Error);
}

TEST(ExpressionTypes, AffineMassesPointsAndVectors) {
  EXPECT_EQ(type_of("n0.position", ValueType::Point).str(), "point");
  EXPECT_EQ(type_of("0.25 * n0.position + 0.75 * n1.position", ValueType::Point).str(), "point");
  EXPECT_EQ(type_of("n0.position - n1.position", ValueType::Vector).str(), "vector");
  EXPECT_EQ(type_of("n0.position + 2 * n0.normal", ValueType::Point).str(), "point");
  EXPECT_EQ(type_of("middle(<0,1>_position(n0))", ValueType::Point).str(), "point");
  // A mass known only at run time is accepted statically (checked at evaluation).
  EXPECT_EQ(type_of("let n = count(<0>_position(n0)) in (n0.position + (n - 1) * n1.position) / n",
                    ValueType::Point)
                .str(),
            "affine combination");
  const auto [where, msg] = error_of("n0.position + n1.position", ValueType::Point);
  EXPECT_EQ(where, "test, column 1");
  EXPECT_NE(msg.find("affine combination of mass 2"), std::string::npos) << msg;
  EXPECT_NE(error_of("n0.position", ValueType::Vector).second.find("is a point"),
            std::string::npos);
}

TEST(ExpressionTypes, ColoursScalarsAndMultisets) {
  EXPECT_EQ(type_of("clamp(0.5 * n0.colour + colour(1, 0, 0) / 2)", ValueType::Colour).str(),
            "colour");
  EXPECT_EQ(type_of("count(<0,1>_colour(n0)) + cos(pi)", ValueType::Scalar).str(), "scalar");
  EXPECT_NE(error_of("n0.colour + n0.position", ValueType::Colour)
                .second.find("no operator colour + point"),
            std::string::npos);
  EXPECT_NE(error_of("<0,1>_position(n0)", ValueType::Point).second.find("multiset of point"),
            std::string::npos);
  EXPECT_NE(error_of("2 * <0>_position(n0)", ValueType::Point).second.find("no operator"),
            std::string::npos);
  EXPECT_NE(error_of("middle(n0.position)", ValueType::Point).second.find("takes a multiset"),
            std::string::npos);
  EXPECT_NE(error_of("dot(n0.position, n0.normal)", ValueType::Scalar).second.find("takes vectors"),
            std::string::npos);
}

TEST(ExpressionTypes, NamesAreResolved) {
  EXPECT_EQ(error_of("n7.position", ValueType::Point),
            std::make_pair(std::string("test, column 1"), std::string("unknown node n7")));
  EXPECT_NE(error_of("n2.position", ValueType::Point).second.find("added by the rule"),
            std::string::npos);
  EXPECT_NE(error_of("n0.pos", ValueType::Point).second.find("unknown embedding 'pos'"),
            std::string::npos);
  EXPECT_NE(error_of("n0@3.position", ValueType::Point).second.find("outside 0..2"),
            std::string::npos);
  EXPECT_NE(error_of("frobnicate(n0.position)", ValueType::Point).second.find("unknown function"),
            std::string::npos);
  EXPECT_EQ(error_of("n0.position + x", ValueType::Point).first, "test, column 15");
  // Comprehension variables shadow nodes and are scoped to their body.
  EXPECT_EQ(type_of("middle([n1.position | n1 in <1>/<>(n0)])", ValueType::Point).str(), "point");
  EXPECT_EQ(error_of("middle([x.position | x in <1>/<>(n0)]) + x.position - n0.position",
                     ValueType::Point)
                .second,
            "unknown node x");
}

namespace {

struct Square {
  EmbeddedMap m;
  std::vector<EmbeddingSignature> sigs{{"position", OrbitType{1, 2}, ValueType::Point}};
  Square() { m = io::read_off_file(source("model/expr/tests/data/square.off")); }
  Val eval(const std::string& code, Dart d, ValueType t = ValueType::Point) {
    CheckContext c;
    c.nodes = {"n0"};
    c.embeddings = sigs;
    auto e = parse_expression(code);
    check_expression(*e, c, t);
    Evaluator ev(m.map, sigs, {m.find("position")});
    return ev.evaluate(*e, &d, t, "test");
  }
};

}  // namespace

TEST(ExpressionEvaluation, CollectKeepsOneValuePerOrbit) {
  Square sq;
  // The face <0,1>(a) has 8 darts and 4 vertices: 4 values (thesis §5.5.2, Fig. 5.29).
  EXPECT_EQ(sq.eval("count(<0,1>_position(n0))", 0, ValueType::Scalar).x, 4.0);
  EXPECT_EQ(sq.eval("count([x.position | x in <0,1>/<>(n0)])", 0, ValueType::Scalar).x, 8.0);
  const Val c = sq.eval("middle(<0,1>_position(n0))", 0);
  EXPECT_DOUBLE_EQ(c.x, 0.5);
  EXPECT_DOUBLE_EQ(c.y, 0.5);
  EXPECT_EQ(sq.eval("count([0 | x, k in (@0@1)*(n0)])", 0, ValueType::Scalar).x, 4.0);
}

TEST(ExpressionEvaluation, NeighboursReadLeftToRight) {
  Square sq;
  for (Dart d : sq.m.map.darts()) {
    const Vec3 p = sq.m.find("position")->values.get(sq.m.map.alpha(0, sq.m.map.alpha(1, d)));
    const Val v = sq.eval("n0@1@0.position", d);
    EXPECT_EQ(v.x, p[0]);
    EXPECT_EQ(v.y, p[1]);
  }
}

TEST(ExpressionEvaluation, RunTimeMassIsChecked) {
  Square sq;
  EXPECT_NO_THROW(sq.eval(
      "let n = count(<0,1>_position(n0)) in (n0.position + (n - 1) * n0@0.position) / n", 0));
  try {
    sq.eval("let n = count(<0,1>_position(n0)) in (n0.position + n * n0@0.position) / n", 0);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(e.message().find("weights sum to 1.25"), std::string::npos) << e.message();
    EXPECT_EQ(e.location(), "test, column 1, dart 0");
  }
}

namespace {

scheme::RuleScheme vertex_insertion() {
  return io::read_scheme_file(source("tools/data/rules/vertex_insertion.json"));
}

}  // namespace

TEST(ExpressionPropagation, VertexInsertionGivesMidpoints) {
  const scheme::RuleScheme s = vertex_insertion();
  const CompiledScheme cs = compile_scheme(s);
  Square sq;
  EmbeddingPropagation p(cs, sq.m);
  const auto all = scheme::apply_everywhere(scheme::SchemeEngine(s), sq.m.map,
                                            {.keep_tables = false, .observer = &p});
  EXPECT_EQ(all.count(), 4u);
  EXPECT_EQ(p.issue_count(), 0u);
  EXPECT_TRUE(sq.m.find("position")->values.check(sq.m.map).empty());
  std::multiset<std::pair<double, double>> pts;
  for (Dart r : orbit_representatives(sq.m.map, OrbitType{1, 2})) {
    const Vec3 v = sq.m.find("position")->values.get(r);
    pts.insert({v[0], v[1]});
  }
  const std::multiset<std::pair<double, double>> want = {{0, 0},   {1, 0},   {1, 1},   {0, 1},
                                                         {0.5, 0}, {1, 0.5}, {0.5, 1}, {0, 0.5}};
  EXPECT_EQ(pts, want);
}

TEST(ExpressionPropagation, NewOrbitWithoutValueIsReported) {
  scheme::RuleScheme s = vertex_insertion();
  s.right.nodes[1].expressions.clear();
  const CompiledScheme cs = compile_scheme(s);
  Square sq;
  EmbeddingPropagation p(cs, sq.m);
  scheme::apply(scheme::SchemeEngine(s), sq.m.map, {0}, &p);
  ASSERT_EQ(p.issue_count(), 1u);
  EXPECT_EQ(p.issues()[0].code, "E-no-value");
}

TEST(ExpressionPropagation, TwoValuesOnOneOrbitAreReported) {
  // Two hooks with different translations matched in one vertex: two classes of R, one orbit of
  // the result (an overlap, thesis Def. 84 / Fig. 5.25).
  scheme::RuleScheme s;
  s.name = "two_translations";
  s.dimension = 2;
  s.embeddings = {{"position", OrbitType{1, 2}, "point"}};
  for (const char* n : {"n0", "n1"}) {
    s.left.add_node(n, OrbitType{});
    s.right.add_node(n, OrbitType{});
    s.hooks.push_back(n);
  }
  s.right.nodes[0].expressions = {{"position", "n0.position + vector(0, 0, 1)", {}, {}}};
  s.right.nodes[1].expressions = {{"position", "n1.position + vector(0, 0, 2)", {}, {}}};
  const CompiledScheme cs = compile_scheme(s);
  Square sq;
  const Dart d = 0, e = sq.m.map.alpha(1, 0);  // one vertex
  EmbeddingPropagation p(cs, sq.m);
  ASSERT_TRUE(scheme::apply(scheme::SchemeEngine(s), sq.m.map, {d, e}, &p));
  ASSERT_EQ(p.issue_count(), 1u);
  EXPECT_EQ(p.issues()[0].code, "E-overlap");
  // Two different vertices: no overlap, each vertex moves.
  Square sq2;
  const Dart f = sq2.m.map.alpha(0, 0);
  EmbeddingPropagation q(cs, sq2.m);
  ASSERT_TRUE(scheme::apply(scheme::SchemeEngine(s), sq2.m.map, {d, f}, &q));
  EXPECT_EQ(q.issue_count(), 0u);
  EXPECT_EQ(sq2.m.find("position")->values.get(sq2.m.map.alpha(1, 0))[2], 1.0);  // the whole vertex
  EXPECT_EQ(sq2.m.find("position")->values.get(f)[2], 2.0);
}

TEST(ExpressionReader, LocatesExpressionErrors) {
  const std::string doc = R"({
  "format": "gmr.rule", "version": 1, "kind": "scheme", "name": "q", "map": "gmap", "n": 2,
  "orbit": "<0,1,2>", "hooks": ["n0"],
  "embeddings": [{"name": "position", "orbit": "<1,2>", "type": "point"}],
  "left": {"nodes": [{"name": "n0", "orbit": "<0,1,2>"}], "arcs": []},
  "right": {"nodes": [{"name": "n0", "orbit": "<_,1,2>"},
                      {"name": "n1", "orbit": "<_,_,2>", "expressions": [{"embedding": "position", "code": "middle(<0>_position(n0) + 1"}]}],
            "arcs": [{"nodes": ["n0", "n1"], "label": 0}]}
})";
  try {
    io::parse_scheme(doc, "q.json");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.location(),
              "q.json:$.right.nodes[1].expressions[0].code (rule q, node n1), column 28");
  }
  std::string undeclared = doc;
  undeclared.replace(undeclared.find("\"embedding\": \"position\""), 23,
                     "\"embedding\": \"colour\"");
  try {
    io::parse_scheme(undeclared, "q.json");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.location(), "q.json:$.right.nodes[1].expressions[0].embedding");
  }
}

TEST(ExpressionReader, EmbeddingsRoundTrip) {
  for (const char* f :
       {"quad_subdivision", "loop_subdivision", "sqrt3_subdivision", "doo_sabin_subdivision"}) {
    const scheme::RuleScheme s =
        io::read_scheme_file(source(std::string("tools/data/rules/") + f + ".json"));
    ASSERT_EQ(s.embeddings.size(), 1u);
    EXPECT_EQ(io::parse_scheme(io::scheme_to_json_text(s)), s) << f;
    EXPECT_NO_THROW(compile_scheme(s));
  }
}

TEST(ExpressionEvaluation, CollectOnAFaceThroughOneVertexFourTimes) {
  // The 1x1 torus: one square face whose four corners are one vertex. One value, not four
  // (thesis §5.5.2); the face's pieces share a slot, so the evaluator marks the vertex orbit.
  EmbeddedMap m;
  m.map = Map(2);
  m.map.add_darts(8);  // the square's darts in order; bottom 0-1, right 2-3, top 4-5, left 6-7
  for (Dart k = 0; k < 8; k += 2) m.map.link(0, k, k + 1);
  for (Dart k = 1; k < 8; k += 2) m.map.link(1, k, (k + 1) % 8);
  m.map.link(2, 0, 5);  // bottom glued to top, right to left
  m.map.link(2, 1, 4);
  m.map.link(2, 2, 7);
  m.map.link(2, 3, 6);
  ASSERT_TRUE(check_validity(m.map).ok());
  EmbeddingField pos = EmbeddingField::numeric("position", OrbitType{1, 2});
  for (Dart r : orbit_representatives(m.map, OrbitType{1, 2})) pos.values.set(m.map, r, {1, 2, 3});
  m.fields.push_back(std::move(pos));
  ASSERT_EQ(count_orbits(m.map, OrbitType{1, 2}), 1u);
  const std::vector<EmbeddingSignature> sigs{{"position", OrbitType{1, 2}, ValueType::Point}};
  CheckContext c;
  c.nodes = {"n0"};
  c.embeddings = sigs;
  auto e = parse_expression("count(<0,1>_position(n0))");
  check_expression(*e, c, ValueType::Scalar);
  Evaluator ev(m.map, sigs, {m.find("position")});
  Dart d = 0;
  EXPECT_EQ(ev.evaluate(*e, &d, ValueType::Scalar, "test").x, 1.0);
}
