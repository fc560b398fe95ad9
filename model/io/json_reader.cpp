#include "model/io/json_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace gmr::io {

nlohmann::json parse_json(std::string_view text, const std::string& source) {
  try {
    return nlohmann::json::parse(text.begin(), text.end());
  } catch (const nlohmann::json::parse_error& e) {
    // e.byte is the 1-based offset of the last character read; turn it into line:column.
    const size_t end = std::min(e.byte > 0 ? e.byte - 1 : 0, text.size());
    size_t line = 1, col = 1;
    for (size_t k = 0; k < end; ++k) {
      if (text[k] == '\n') {
        ++line;
        col = 1;
      } else {
        ++col;
      }
    }
    // nlohmann's message: "[json.exception.parse_error.101] parse error at line 3, column 5: <what>".
    std::string what = e.what();
    const size_t column_at = what.find("column ");
    const size_t colon = what.find(": ", column_at == std::string::npos ? 0 : column_at);
    if (colon != std::string::npos) what = what.substr(colon + 2);
    std::string loc = std::to_string(line) + ":" + std::to_string(col);
    throw Error(ErrorCode::Parse, "malformed JSON: " + what, source.empty() ? "line " + loc : source + ":" + loc);
  }
}

std::string json_path_key(std::string_view key) {
  const bool plain = !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
  if (plain) return "." + std::string(key);
  return "[" + nlohmann::json(std::string(key)).dump() + "]";
}

std::string describe_json(const nlohmann::json& v) {
  switch (v.type()) {
    case nlohmann::json::value_t::object: return "an object";
    case nlohmann::json::value_t::array: return "an array";
    case nlohmann::json::value_t::string: return "the string " + v.dump();
    case nlohmann::json::value_t::boolean: return v.get<bool>() ? "true" : "false";
    case nlohmann::json::value_t::null: return "null";
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
    case nlohmann::json::value_t::number_float: return "the number " + v.dump();
    default: return "a " + std::string(v.type_name());
  }
}

std::string JsonAt::location_of(const std::string& path) const {
  return source_.empty() ? path : source_ + ":" + path;
}

void JsonAt::fail(const std::string& message, ErrorCode code) const { fail_at(path_, message, code); }

void JsonAt::fail_at(const std::string& path, const std::string& message, ErrorCode code) const {
  throw Error(code, message, location_of(path));
}

void JsonAt::require_object() const {
  if (!v_->is_object()) fail("expected an object, found " + describe_json(*v_));
}

bool JsonAt::has(std::string_view key) const {
  require_object();
  auto it = v_->find(key);
  return it != v_->end() && !it->is_null();
}

JsonAt JsonAt::operator[](std::string_view key) const {
  require_object();
  auto it = v_->find(key);
  if (it == v_->end()) fail("missing member \"" + std::string(key) + "\"");
  return JsonAt(*it, source_, child_path(key));
}

std::optional<JsonAt> JsonAt::get(std::string_view key) const {
  require_object();
  auto it = v_->find(key);
  if (it == v_->end() || it->is_null()) return std::nullopt;
  return JsonAt(*it, source_, child_path(key));
}

void JsonAt::allow_only(std::initializer_list<std::string_view> keys) const {
  require_object();
  for (auto it = v_->begin(); it != v_->end(); ++it) {
    if (std::find(keys.begin(), keys.end(), it.key()) == keys.end()) {
      std::string known;
      for (auto k : keys) known += (known.empty() ? "" : ", ") + std::string(k);
      fail_at(child_path(it.key()), "unknown member \"" + it.key() + "\" (expected: " + known + ")");
    }
  }
}

size_t JsonAt::array_size() const {
  if (!v_->is_array()) fail("expected an array, found " + describe_json(*v_));
  return v_->size();
}

JsonAt JsonAt::operator[](size_t i) const {
  if (i >= array_size()) fail("index " + std::to_string(i) + " beyond the array's end");
  return JsonAt((*v_)[i], source_, child_path(i));
}

std::string JsonAt::as_string() const {
  if (!v_->is_string()) fail("expected a string, found " + describe_json(*v_));
  return v_->get<std::string>();
}

int64_t JsonAt::as_int(int64_t lo, int64_t hi) const {
  const std::string range = " in " + std::to_string(lo) + ".." + std::to_string(hi);
  if (v_->is_number_unsigned()) {
    const uint64_t u = v_->get<uint64_t>();
    if (hi < 0 || u > static_cast<uint64_t>(hi) || (lo > 0 && u < static_cast<uint64_t>(lo)))
      fail("expected an integer" + range + ", found " + v_->dump());
    return static_cast<int64_t>(u);
  }
  if (!v_->is_number_integer()) fail("expected an integer" + range + ", found " + describe_json(*v_));
  const int64_t x = v_->get<int64_t>();
  if (x < lo || x > hi) fail("expected an integer" + range + ", found " + v_->dump());
  return x;
}

double JsonAt::as_number() const {
  if (!v_->is_number()) fail("expected a number, found " + describe_json(*v_));
  const double x = v_->get<double>();
  if (!std::isfinite(x)) fail("expected a finite number");
  return x;
}

bool JsonAt::as_bool() const {
  if (!v_->is_boolean()) fail("expected true or false, found " + describe_json(*v_));
  return v_->get<bool>();
}

int JsonAt::check_header(std::string_view format, int max_version) const {
  require_object();
  const JsonAt f = (*this)["format"];
  if (!f.value().is_string() || f.value().get<std::string>() != format)
    f.fail("expected \"" + std::string(format) + "\", found " + describe_json(f.value()));
  const JsonAt v = (*this)["version"];
  if (!v.value().is_number_integer() || v.value().get<int64_t>() < 1 || v.value().get<int64_t>() > max_version)
    v.fail("unsupported version " + v.value().dump() + " (this reader knows 1.." + std::to_string(max_version) + ")");
  return static_cast<int>(v.value().get<int64_t>());
}

}  // namespace gmr::io
