// Path-located JSON access (model/json_reader.hpp) and the JSON layout writer (json_writer.hpp).
#include "model/map_io/json_reader.hpp"

#include <gtest/gtest.h>

#include "model/map_io/json_writer.hpp"

using namespace gmr;
using namespace gmr::io;

TEST(JsonReader, PathsAndLocations) {
  EXPECT_EQ(json_path_key("alpha"), ".alpha");
  EXPECT_EQ(json_path_key("1"), ".1");
  EXPECT_EQ(json_path_key("a b"), "[\"a b\"]");
  const nlohmann::json doc = parse_json(R"({"a": {"b c": [1, "x", 2.5]}})");
  const JsonAt root(doc, "f.json");
  const JsonAt arr = root["a"]["b c"];
  EXPECT_EQ(arr.path(), "$.a[\"b c\"]");
  EXPECT_EQ(arr[1].location(), "f.json:$.a[\"b c\"][1]");
  EXPECT_EQ(arr[0].as_int(0, 5), 1);
  EXPECT_DOUBLE_EQ(arr[2].as_number(), 2.5);
  try {
    arr[1].as_int(0, 5);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Schema);
    EXPECT_EQ(e.location(), "f.json:$.a[\"b c\"][1]");
    EXPECT_EQ(e.message(), "expected an integer in 0..5, found the string \"x\"");
  }
  EXPECT_THROW(arr[0].as_int(2, 5), Error);
  EXPECT_THROW(root["zzz"], Error);
  EXPECT_FALSE(root.get("zzz").has_value());
  try {
    root.allow_only({"b"});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.location(), "f.json:$.a");
  }
}

TEST(JsonReader, ParseErrorsGiveLineAndColumn) {
  try {
    parse_json("{\n  \"a\": 1,\n  \"b\": ]\n}", "f.json");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Parse);
    EXPECT_EQ(e.location(), "f.json:3:8");
    EXPECT_EQ(e.message().find("[json.exception"), std::string::npos) << e.message();
  }
}

// Error of parse_json on `text`, or an empty Error when it parses.
Error parse_failure(const std::string& text) {
  try {
    parse_json(text, "f.json");
  } catch (const Error& e) {
    return e;
  }
  return Error(ErrorCode::Usage, "");
}

TEST(JsonReader, DuplicateMemberIsAnErrorAtItsPath) {
  const Error e = parse_failure(R"({"alpha": {"0": [0], "1": [0], "0": [0]}})");
  EXPECT_EQ(e.code(), ErrorCode::Parse);
  EXPECT_EQ(e.location(), "f.json:$.alpha.0");
  EXPECT_NE(e.message().find("duplicate member \"0\""), std::string::npos) << e.message();
}

TEST(JsonReader, NestingBeyondTheLimitIsAnErrorBeforeReadingTheRest) {
  EXPECT_NO_THROW(parse_json(std::string(kMaxJsonDepth, '[') + std::string(kMaxJsonDepth, ']')));
  // A deep value and 10^6 unclosed brackets: refused at the first level too deep.
  const Error e = parse_failure(R"({"v": )" + std::string(1000000, '['));
  EXPECT_EQ(e.code(), ErrorCode::Parse);
  EXPECT_NE(e.message().find("nesting deeper than 100"), std::string::npos) << e.message();
  EXPECT_EQ(e.location().rfind("f.json:$.v[0][0]", 0), 0u) << e.location();
}

TEST(JsonReader, NumberOverflowIsLocatedWithoutLibraryText) {
  const Error e = parse_failure("{\n \"x\": 1e999}");
  EXPECT_EQ(e.code(), ErrorCode::Parse);
  EXPECT_EQ(e.location(), "f.json:2:11");
  EXPECT_EQ(e.message().find("json.exception"), std::string::npos) << e.message();
  EXPECT_NE(e.message().find("1e999"), std::string::npos) << e.message();
}

TEST(JsonWriter, LayoutKeepsOrderAndInlinesScalarArrays) {
  nlohmann::ordered_json j;
  j["format"] = "gmr.test";
  j["version"] = 1;
  j["darts"] = std::vector<int>(200, 7);
  j["small"] = {{"dart", 0}, {"value", {1, 2, 3}}};
  const std::string text = dump_json(j);
  EXPECT_EQ(text.rfind("{\n  \"format\": \"gmr.test\",\n  \"version\": 1,\n  \"darts\": [7,7,", 0),
            0u)
      << text;
  EXPECT_NE(text.find("  \"small\": {\"dart\":0,\"value\":[1,2,3]}\n}\n"), std::string::npos)
      << text;
  EXPECT_EQ(nlohmann::ordered_json::parse(text), j);
}
