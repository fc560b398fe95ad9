#include "model/map_io/json_writer.hpp"

#include <algorithm>

namespace gmr::io {

namespace {

constexpr size_t kInlineWidth = 100;

bool scalar_array(const nlohmann::ordered_json& v) {
  return v.is_array() &&
         std::all_of(v.begin(), v.end(), [](const auto& x) { return !x.is_structured(); });
}

void write(const nlohmann::ordered_json& v, int indent, std::string& out) {
  if (!v.is_structured() || v.empty() || scalar_array(v)) {
    out += v.dump();
    return;
  }
  std::string compact = v.dump();
  if (compact.size() <= kInlineWidth) {
    out += compact;
    return;
  }
  const std::string pad(static_cast<size_t>(indent + 2), ' ');
  out += v.is_object() ? "{\n" : "[\n";
  bool first = true;
  for (auto it = v.begin(); it != v.end(); ++it) {
    if (!first) out += ",\n";
    first = false;
    out += pad;
    if (v.is_object()) out += nlohmann::ordered_json(it.key()).dump() + ": ";
    write(*it, indent + 2, out);
  }
  out += "\n" + std::string(static_cast<size_t>(indent), ' ') + (v.is_object() ? "}" : "]");
}

}  // namespace

std::string dump_json(const nlohmann::ordered_json& value) {
  std::string out;
  write(value, 0, out);
  out += "\n";
  return out;
}

}  // namespace gmr::io
