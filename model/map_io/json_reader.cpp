#include "model/map_io/json_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <vector>

namespace gmr::io {

namespace {

// "line:column" of byte offset `end` in `text`.
std::string line_column(std::string_view text, size_t end) {
  end = std::min(end, text.size());
  size_t line = 1, col = 1;
  for (size_t k = 0; k < end; ++k) {
    if (text[k] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  return std::to_string(line) + ":" + std::to_string(col);
}

// Builds the document from nlohmann's SAX events, rejecting what the DOM parser accepts silently:
// a member name given twice in one object (nlohmann keeps the last) and nesting deeper than
// kMaxJsonDepth (the writers and the destructor recurse per level). Problems are located by path.
class DomBuilder : public nlohmann::json_sax<nlohmann::json> {
 public:
  DomBuilder(std::string_view text, const std::string& source) : text_(text), source_(source) {}
  nlohmann::json take() { return std::move(root_); }

  bool null() override { return add(nullptr); }
  bool boolean(bool v) override { return add(v); }
  bool number_integer(number_integer_t v) override { return add(v); }
  bool number_unsigned(number_unsigned_t v) override { return add(v); }
  bool number_float(number_float_t v, const string_t&) override { return add(v); }
  bool string(string_t& v) override { return add(std::move(v)); }
  bool binary(binary_t&) override { return fail_here("binary values are not JSON"); }
  bool start_object(std::size_t) override { return open(nlohmann::json::object()); }
  bool start_array(std::size_t) override { return open(nlohmann::json::array()); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }
  bool key(string_t& k) override {
    Frame& top = stack_.back();
    if (top.node->contains(k))
      throw Error(ErrorCode::Parse,
                  "duplicate member \"" + k + "\" (JSON objects name each member once)",
                  located(top.path + json_path_key(k)));
    top.key = std::move(k);
    return true;
  }
  bool parse_error(std::size_t position, const std::string&,
                   const nlohmann::detail::exception& e) override {
    // nlohmann's message: "[json.exception.<kind>.<id>] [parse error at line 3, column 5: ]<what>".
    std::string what = e.what();
    const size_t bracket = what.find("] ");
    if (bracket != std::string::npos) what = what.substr(bracket + 2);
    const size_t column_at = what.find("column ");
    if (column_at != std::string::npos) {
      const size_t colon = what.find(": ", column_at);
      if (colon != std::string::npos) what = what.substr(colon + 2);
    }
    // position is the 1-based offset of the last character read.
    const std::string loc = line_column(text_, position > 0 ? position - 1 : 0);
    throw Error(ErrorCode::Parse, "malformed JSON: " + what,
                source_.empty() ? "line " + loc : source_ + ":" + loc);
  }

 private:
  struct Frame {
    nlohmann::json* node;
    std::string path;
    std::string key;  // pending member name (objects)
  };

  std::string located(const std::string& path) const {
    return source_.empty() ? path : source_ + ":" + path;
  }
  std::string next_path() const {
    if (stack_.empty()) return "$";
    const Frame& top = stack_.back();
    return top.node->is_array() ? top.path + "[" + std::to_string(top.node->size()) + "]"
                                : top.path + json_path_key(top.key);
  }
  bool fail_here(const std::string& message) const {
    throw Error(ErrorCode::Parse, message, located(next_path()));
  }

  nlohmann::json* place(nlohmann::json&& v) {
    if (stack_.empty()) {
      root_ = std::move(v);
      return &root_;
    }
    Frame& top = stack_.back();
    if (top.node->is_array()) {
      top.node->push_back(std::move(v));
      return &top.node->back();
    }
    nlohmann::json& slot = (*top.node)[top.key];
    slot = std::move(v);
    return &slot;
  }
  bool add(nlohmann::json&& v) {
    place(std::move(v));
    return true;
  }
  bool open(nlohmann::json&& container) {
    if (stack_.size() >= kMaxJsonDepth)
      fail_here("nesting deeper than " + std::to_string(kMaxJsonDepth) +
                " levels of arrays and objects");
    std::string path = next_path();
    nlohmann::json* node = place(std::move(container));
    stack_.push_back(Frame{node, std::move(path), {}});
    return true;
  }
  bool close() {
    stack_.pop_back();
    return true;
  }

  std::string_view text_;
  const std::string& source_;
  nlohmann::json root_;
  std::vector<Frame> stack_;
};

}  // namespace

nlohmann::json parse_json(std::string_view text, const std::string& source) {
  DomBuilder builder(text, source);
  nlohmann::json::sax_parse(text.begin(), text.end(), &builder);
  return builder.take();
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
    case nlohmann::json::value_t::object:
      return "an object";
    case nlohmann::json::value_t::array:
      return "an array";
    case nlohmann::json::value_t::string:
      return "the string " + v.dump();
    case nlohmann::json::value_t::boolean:
      return v.get<bool>() ? "true" : "false";
    case nlohmann::json::value_t::null:
      return "null";
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
    case nlohmann::json::value_t::number_float:
      return "the number " + v.dump();
    default:
      return "a " + std::string(v.type_name());
  }
}

std::string JsonAt::location_of(const std::string& path) const {
  return source_.empty() ? path : source_ + ":" + path;
}

void JsonAt::fail(const std::string& message, ErrorCode code) const {
  fail_at(path_, message, code);
}

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
      fail_at(child_path(it.key()),
              "unknown member \"" + it.key() + "\" (expected: " + known + ")");
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
  if (!v_->is_number_integer())
    fail("expected an integer" + range + ", found " + describe_json(*v_));
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
  if (!v.value().is_number_integer() || v.value().get<int64_t>() < 1 ||
      v.value().get<int64_t>() > max_version)
    v.fail("unsupported version " + v.value().dump() + " (this reader knows 1.." +
           std::to_string(max_version) + ")");
  return static_cast<int>(v.value().get<int64_t>());
}

}  // namespace gmr::io
