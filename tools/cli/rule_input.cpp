#include "tools/cli/rule_input.hpp"

#include <filesystem>

#include "model/core/error.hpp"
#include "model/map_io/json_reader.hpp"
#include "model/map_io/read_file.hpp"
#include "model/rule_io/jme_import.hpp"
#include "model/rule_io/rule_json.hpp"
#include "model/rule_io/scheme_json.hpp"

namespace gmr::cli {
using namespace gmr::io;

namespace {

std::string extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace

bool is_rule_file(const std::string& path) {
  if (path == "-") return false;
  const std::string ext = extension(path);
  if (ext == ".jme") return true;
  if (ext != ".json") return false;
  const nlohmann::json doc = parse_json(read_text_file(path), path);
  return doc.is_object() && doc.contains("format") && doc["format"] == "gmr.rule";
}

RuleInput load_rule_input(const std::string& path, const std::string& rule_name) {
  RuleInput in;
  if (extension(path) == ".jme") {
    JmeModeler m = read_jme_file(path);
    if (m.rules.empty()) throw Error(ErrorCode::Schema, "the Jerboa file has no rule", path);
    if (rule_name.empty()) {
      if (m.rules.size() > 1)
        throw Error(ErrorCode::Usage,
                    "the Jerboa file has " + std::to_string(m.rules.size()) +
                        " rules (first: " + m.rules[0].name + "); pick one with --rule NAME",
                    path);
      in.scheme = std::move(m.rules[0]);
      return in;
    }
    for (auto& r : m.rules)
      if (r.name == rule_name) {
        in.scheme = std::move(r);
        return in;
      }
    std::string names;
    for (const auto& r : m.rules) names += (names.empty() ? "" : ", ") + r.name;
    throw Error(ErrorCode::Usage,
                "no rule \"" + rule_name + "\" in the Jerboa file (rules: " + names + ")", path);
  }
  const nlohmann::json doc = parse_json(read_text_file(path), path);
  if (rule_document_kind(doc, path) == "scheme")
    in.scheme = scheme_from_json(doc, path);
  else
    in.concrete = rule_from_json(doc, path);
  const std::string& name = in.scheme ? in.scheme->name : in.concrete->name();
  if (!rule_name.empty() && rule_name != name)
    throw Error(ErrorCode::Usage, "the file holds rule \"" + name + "\", not \"" + rule_name + "\"",
                "--rule");
  return in;
}

}  // namespace gmr::cli
