// Rule files on the command line (`gmr dot`, `gmr apply`): a gmr.rule JSON document (kind
// "concrete" or "scheme", told by its "kind" member) or a Jerboa .jme file (one of its rules,
// picked by name). Anything else is not a rule input (the caller treats it as a map).
#pragma once
#include <optional>
#include <string>

#include "model/rewrite/rule.hpp"
#include "model/scheme/rule_scheme.hpp"

namespace gmr::cli {
using rewrite::Rule;
using scheme::RuleScheme;

struct RuleInput {
  std::optional<Rule> concrete;
  std::optional<RuleScheme> scheme;
  bool is_scheme() const { return scheme.has_value(); }
};

// True when `path` names a .jme file or a JSON document whose "format" is "gmr.rule".
bool is_rule_file(const std::string& path);

// Reads the rule. `rule_name` picks a rule of a .jme file (required when it holds several; then
// Error(Usage) lists the names); it must be empty or equal to the rule's name for a gmr.rule file.
// Malformed files throw the readers' located errors.
RuleInput load_rule_input(const std::string& path, const std::string& rule_name = {});

}  // namespace gmr::cli
