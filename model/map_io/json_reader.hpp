// Path-located reading of JSON documents, shared by the gmr.* file readers.
//
// Every file starts with "format": "gmr.<kind>" and "version"; readers
// validate everything and report the first problem with its JSON path. Paths use the notation
// `$` (the document), `.key` (object member; `["odd key"]` when the key is not a plain word) and
// `[i]` (array element), e.g. `$.alpha.1[7]` or `$.embeddings[0].values[3].dart`.
// Locations are "<source>:<path>" when the document has a source name (a file), else "<path>".
// Malformed JSON is Error(Parse) located "<source>:<line>:<column>"; structural problems are
// Error(Schema) located by path.
#pragma once
#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "model/core/error.hpp"

namespace gmr::io {

// Nesting limit of parse_json: deeper documents are Error(Parse) located by path.
inline constexpr size_t kMaxJsonDepth = 100;

// Parses a JSON document. Besides malformed text (located line:column), rejects a member name
// given twice in one object and nesting deeper than kMaxJsonDepth (located by path).
nlohmann::json parse_json(std::string_view text, const std::string& source = {});

// `.key` or `["key"]`, as appended to a path.
std::string json_path_key(std::string_view key);

// A JSON value together with its path in the document. Holds a reference: the document must
// outlive it.
class JsonAt {
 public:
  JsonAt(const nlohmann::json& value, std::string source, std::string path = "$")
      : v_(&value), source_(std::move(source)), path_(std::move(path)) {}

  const nlohmann::json& value() const { return *v_; }
  const std::string& path() const { return path_; }
  const std::string& source() const { return source_; }
  std::string location() const { return location_of(path_); }
  std::string location_of(const std::string& path) const;
  std::string child_path(std::string_view key) const { return path_ + json_path_key(key); }
  std::string child_path(size_t i) const { return path_ + "[" + std::to_string(i) + "]"; }

  [[noreturn]] void fail(const std::string& message, ErrorCode code = ErrorCode::Schema) const;
  [[noreturn]] void fail_at(const std::string& path, const std::string& message,
                            ErrorCode code = ErrorCode::Schema) const;

  // --- objects ---
  void require_object() const;
  bool has(std::string_view key) const;
  JsonAt operator[](std::string_view key) const;          // required member
  std::optional<JsonAt> get(std::string_view key) const;  // optional member (absent or null)
  // Rejects any member not in `keys`, naming the first unknown one (in document order).
  void allow_only(std::initializer_list<std::string_view> keys) const;

  // --- arrays ---
  size_t array_size() const;  // requires an array
  JsonAt operator[](size_t i) const;

  // --- scalars ---
  std::string as_string() const;
  int64_t as_int(int64_t lo, int64_t hi) const;  // an integer in [lo, hi]
  double as_number() const;                      // a finite number
  bool as_bool() const;

  // Checks that this is an object with "format": "<format>" and "version" an integer in
  // [1, max_version]; returns the version.
  int check_header(std::string_view format, int max_version) const;

 private:
  const nlohmann::json* v_;
  std::string source_;
  std::string path_;
};

// "an object", "a string", "the number 1.5", ... for messages.
std::string describe_json(const nlohmann::json& v);

}  // namespace gmr::io
