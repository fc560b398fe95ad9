// The static checker as a gate before `gmr apply`: a rule the checker rejects (concrete rules:
// checker/rule_check.hpp; rule schemes: checker/scheme_checker.hpp) is not applied unless the user
// forces it, since its application may break the map (thesis Thms. 1-3 and 4-6). A Jerboa
// precondition is code gmr does not run: its presence is reported on every application.
#pragma once
#include <optional>
#include <string>

#include "tools/cli/rule_input.hpp"

namespace gmr::cli {

// nullopt when the rule may be applied (accepted, or `force`); else prints the refusal (standard
// error: the verdict, the first error, how to see all and how to force) and returns exit code 1.
// Warnings (forced application, unevaluated precondition) go to standard error. Without
// `embeddings` (apply --no-embeddings), the topological conditions only.
std::optional<int> gate_rule(const RuleInput& in, const std::string& path, bool force,
                             bool embeddings);

}  // namespace gmr::cli
