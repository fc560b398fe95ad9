// gmr.gmap reading and writing (model/io_json.hpp): round trips up to isomorphism with the same
// embeddings, and the first problem of a malformed file located by JSON path or line:column.
#include "model/map_io/map_json.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

#include "model/core/builders.hpp"
#include "model/core/signature.hpp"
#include "model/core/validity.hpp"
#include "model/map_io/face_list.hpp"
#include "model/map_io/off.hpp"
#include "model/testing/source_tree.hpp"

using namespace gmr;
using namespace gmr::io;

namespace {

std::string data(const std::string& name) {
  return gmr::testing::source_path("model/map_io/tests/data/" + name);
}

// A gmr.gmap text of a 1-G-map with 4 darts, `alpha1` spliced in.
std::string tiny(const std::string& alpha1, const std::string& extra = "") {
  return R"({"format": "gmr.gmap", "version": 1, "kind": "gmap", "dimension": 1, "darts": 4,
  "alpha": {"0": [1, 0, 3, 2], "1": )" +
         alpha1 + "}" + extra + "}";
}

// Expects read_map_json(text) to throw `code` with exactly `location` and a message containing
// `what`.
void expect_error(const std::string& text, ErrorCode code, const std::string& location,
                  const std::string& what = "") {
  try {
    read_map_json(text);
    FAIL() << "no error; expected " << location;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), code) << e.what();
    EXPECT_EQ(e.location(), location) << e.what();
    EXPECT_NE(e.message().find(what), std::string::npos) << e.what();
  }
}

void expect_same_embeddings(const EmbeddedMap& a, const EmbeddedMap& b) {
  ASSERT_EQ(a.fields.size(), b.fields.size());
  for (size_t k = 0; k < a.fields.size(); ++k) {
    const auto& ea = a.fields[k];
    const auto& eb = b.fields[k];
    EXPECT_EQ(ea.name(), eb.name());
    EXPECT_EQ(ea.orbit(), eb.orbit());
    EXPECT_EQ(ea.arity, eb.arity);
    // Dense maps keep their dart numbering, so values compare dart by dart.
    a.map.for_each_dart([&](Dart d) {
      ASSERT_EQ(ea.has(d), eb.has(d)) << "dart " << d;
      if (ea.has(d)) {
        EXPECT_EQ(ea.value_json(d), eb.value_json(d)) << "dart " << d;
      }
    });
  }
}

}  // namespace

TEST(IoJson, RoundTripCubeWithPositions) {
  const EmbeddedMap cube = read_off_file(gmr::testing::source_path("tools/data/cube.off"));
  EmbeddedMap f = cube;
  f.fields.push_back(EmbeddingField::of_json("label", OrbitType{0, 1}));
  f.fields.back().json->set(f.map, 0, nlohmann::json{{"colour", "red"}, {"weight", 2.5}});
  const std::string text = write_map_json(f);
  EXPECT_EQ(text.rfind("{\n  \"format\": \"gmr.gmap\",\n  \"version\": 1,", 0), 0u)
      << text.substr(0, 80);
  const EmbeddedMap back = read_map_json(text);
  EXPECT_TRUE(is_isomorphic(f.map, back.map));
  expect_same_embeddings(f, back);
  EXPECT_EQ(write_map_json(back), text);
}

TEST(IoJson, RoundTripStackedCubesAndOMap) {
  for (const Map& g : {make_stacked_cubes(), orient(make_cube()), make_grid(2, 3), Map(0)}) {
    const EmbeddedMap back = read_map_json(write_map_json(g));
    EXPECT_EQ(back.map.kind(), g.kind());
    EXPECT_EQ(back.map.dimension(), g.dimension());
    EXPECT_EQ(back.map.size(), g.size());
    EXPECT_TRUE(is_isomorphic(g, back.map));
    EXPECT_TRUE(is_valid(back.map));
  }
}

TEST(IoJson, DeletedDartsAreCompacted) {
  Map g = make_cube();
  const Dart extra = g.add_dart();
  const Dart first_square = g.add_darts(8);
  (void)first_square;
  g.remove_dart(extra);  // leaves a hole at `extra`
  ASSERT_TRUE(g.has_holes());
  const EmbeddedMap back = read_map_json(write_map_json(g));
  EXPECT_EQ(back.map.size(), g.size());
  EXPECT_FALSE(back.map.has_holes());
  EXPECT_TRUE(is_valid(back.map));
}

TEST(IoJson, ReadsDataFile) {
  const EmbeddedMap f = read_map_json_file(data("square.json"));
  EXPECT_EQ(f.map.size(), 8u);
  EXPECT_TRUE(is_valid(f.map));
  ASSERT_NE(f.find("position"), nullptr);
  EXPECT_EQ(f.find("position")->arity, 3);  // triples are typed on reading
  EXPECT_EQ(f.position().get(3), (Vec3{1, 1, 0}));
  EXPECT_EQ(f.find("position")->value_json(4),
            nlohmann::json::array({1, 1, 0}));  // same <1,2>-orbit as 3
  EXPECT_TRUE(f.find("position")->check(f.map).empty());
}

// Values are typed on reading (embedded_map.hpp): numbers and triples become numbers and are
// written back equal as JSON numbers (an embedding of integers only, such as flags, as integers),
// and anything else (booleans, strings, a mix of numbers and triples, integers beyond 2^53) stays
// JSON, written back unchanged.
TEST(IoJson, ValuesAreTypedOnReadingAndWrittenBackAsRead) {
  auto map_with = [](const std::string& values) {
    return R"({"format": "gmr.gmap", "version": 1, "kind": "gmap", "dimension": 1, "darts": 2,
               "alpha": {"0": [1, 0], "1": [0, 1]}, "embeddings": [{"name": "w", "orbit": "<>", "values": )" +
           values + "}]}";
  };
  struct Case {
    std::string values;
    int arity;
    bool same_text;  // written back to the letter
  };
  for (const Case& c :
       {Case{R"([{"dart": 0, "value": 2}, {"dart": 1, "value": -3}])", 1, true},
        Case{R"([{"dart": 0, "value": 0.5}, {"dart": 1, "value": 2}])", 1, false},
        Case{R"([{"dart": 0, "value": [1, 2, 3]}, {"dart": 1, "value": [4, 0, -7]}])", 3, true},
        Case{R"([{"dart": 0, "value": [1, 2, 3]}, {"dart": 1, "value": [0.5, 0, 1e300]}])", 3,
             false},
        Case{R"([{"dart": 0, "value": true}, {"dart": 1, "value": 1}])", 0, true},
        Case{R"([{"dart": 0, "value": 1}, {"dart": 1, "value": [1, 2, 3]}])", 0, true},
        Case{R"([{"dart": 0, "value": 18014398509481985}])", 0, true},
        Case{R"([{"dart": 0, "value": "red"}])", 0, true}}) {
    const nlohmann::json given = nlohmann::json::parse(map_with(c.values));
    const EmbeddedMap m = read_map_json(given.dump());
    ASSERT_EQ(m.fields.size(), 1u);
    EXPECT_EQ(m.fields[0].arity, c.arity) << c.values;
    const nlohmann::json back = nlohmann::json::parse(write_map_json(m));
    EXPECT_EQ(back["embeddings"][0]["values"], given["embeddings"][0]["values"]) << c.values;
    if (c.same_text) {
      EXPECT_EQ(back["embeddings"][0]["values"].dump(), given["embeddings"][0]["values"].dump())
          << c.values;
    }
  }
}

TEST(IoJson, InvalidMapIsReturnedNotRejected) {
  const EmbeddedMap f = read_map_json_file(data("invalid_gmap.json"));
  const ValidityReport r = check_validity(f.map);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.violations.front().constraint, Constraint::Cycle);
  // A non-involutive link is a violation too, not a parse error.
  const EmbeddedMap g = read_map_json(tiny("[1, 1, 3, 3]"));
  EXPECT_FALSE(is_valid(g.map));
}

TEST(IoJson, MalformedJsonGivesLineAndColumn) {
  try {
    read_map_json_file(data("bad_syntax.json"));
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Parse);
    EXPECT_EQ(e.location(), data("bad_syntax.json") + ":4:8");
  }
  expect_error("{\"format\": ", ErrorCode::Parse, "line 1:12", "malformed JSON");
  expect_error("", ErrorCode::Parse, "line 1:1");
}

TEST(IoJson, SchemaErrorsAreLocatedByPath) {
  expect_error("[]", ErrorCode::Schema, "$", "expected an object");
  expect_error(R"({"version": 1})", ErrorCode::Schema, "$", "missing member \"format\"");
  expect_error(R"({"format": "gmr.rule", "version": 1})", ErrorCode::Schema, "$.format",
               "gmr.gmap");
  expect_error(R"({"format": "gmr.gmap", "version": 2})", ErrorCode::Schema, "$.version",
               "unsupported version 2");
  expect_error(R"({"format": "gmr.gmap", "version": 1, "kind": "cmap"})", ErrorCode::Schema,
               "$.kind");
  expect_error(R"({"format": "gmr.gmap", "version": 1, "kind": "omap", "dimension": 0})",
               ErrorCode::Schema, "$.dimension", "1..30");
  expect_error(
      R"({"format": "gmr.gmap", "version": 1, "kind": "gmap", "dimension": 1, "darts": -1})",
      ErrorCode::Schema, "$.darts");
  expect_error(tiny("[3, 2, 1, 0]", R"(, "colour": 1)"), ErrorCode::Schema, "$.colour",
               "unknown member");
  expect_error(tiny("[3, 2, 1, 7]"), ErrorCode::Schema, "$.alpha.1[3]",
               "dart index 7 out of range");
  expect_error(tiny("[3, 2, -1, 0]"), ErrorCode::Schema, "$.alpha.1[2]", "out of range");
  expect_error(tiny("[3, 2, 1.0, 0]"), ErrorCode::Schema, "$.alpha.1[2]");
  expect_error(tiny("[3, 2, \"1\", 0]"), ErrorCode::Schema, "$.alpha.1[2]", "the string");
  expect_error(tiny("[3, 2, 1]"), ErrorCode::Schema, "$.alpha.1", "expected 4 entries");
  expect_error(tiny("[3, 2, 1, 0], \"2\": [0, 1, 2, 3]"), ErrorCode::Schema, "$.alpha.2",
               "not a dimension");
  expect_error(R"({"format": "gmr.gmap", "version": 1, "kind": "gmap", "dimension": 1, "darts": 2,
    "alpha": {"0": [1, 0]}})",
               ErrorCode::Schema, "$.alpha", "missing member \"1\"");
  expect_error(R"({"format": "gmr.gmap", "version": 1, "kind": "omap", "dimension": 1, "darts": 1,
    "alpha": {"0": [0], "1": [0]}})",
               ErrorCode::Schema, "$.alpha.0", "not a dimension of this omap");
}

TEST(IoJson, EmbeddingErrorsAreLocatedByPath) {
  auto with = [](const std::string& embeddings) {
    return tiny("[3, 2, 1, 0]", ", \"embeddings\": " + embeddings);
  };
  expect_error(with(R"([{"name": "w", "orbit": "<0,2>", "values": []}])"), ErrorCode::Schema,
               "$.embeddings[0].orbit", "dimension");
  expect_error(with(R"([{"name": "w", "orbit": "<0,", "values": []}])"), ErrorCode::Schema,
               "$.embeddings[0].orbit", "bad orbit type");
  expect_error(with(R"([{"name": "w", "orbit": "<0>", "values": [{"dart": 4, "value": 1}]}])"),
               ErrorCode::Schema, "$.embeddings[0].values[0].dart", "out of range");
  expect_error(
      with(
          R"([{"name": "w", "orbit": "<0>", "values": [{"dart": 0, "value": 1}, {"dart": 1, "value": 2}]}])"),
      ErrorCode::Schema, "$.embeddings[0].values[1]",
      "already has a value ($.embeddings[0].values[0])");
  expect_error(with(R"([{"name": "w", "orbit": "<0>", "values": [{"dart": 0}]}])"),
               ErrorCode::Schema, "$.embeddings[0].values[0]", "missing member \"value\"");
  expect_error(
      with(
          R"([{"name": "w", "orbit": "<0>", "values": []}, {"name": "w", "orbit": "<1>", "values": []}])"),
      ErrorCode::Schema, "$.embeddings[1].name", "duplicate");
  // Missing values are allowed (Embedding::check reports them).
  const EmbeddedMap f = read_map_json(
      with(R"([{"name": "w", "orbit": "<0>", "values": [{"dart": 1, "value": null}]}])"));
  EXPECT_EQ(f.find("w")->check(f.map).size(), 1u);
}

TEST(IoJson, FileLocationsNameTheFile) {
  try {
    read_map_json_file(data("dart_out_of_range.json"));
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.location(), data("dart_out_of_range.json") + ":$.alpha.1[3]");
  }
  try {
    read_map_json_file(data("no_such_file.json"));
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Io);
  }
}
