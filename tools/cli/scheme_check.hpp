// `gmr check` for rule schemes: .jme Jerboa files (a summary table over every rule) and
// gmr.rule files of kind "scheme". Called by tools/cli/cmd_check.cpp before its concrete-rule path.
#pragma once
#include <optional>
#include <string>

namespace gmr::cli {

// nullopt when `path` is neither a .jme file nor a gmr.rule document of kind "scheme" (the caller
// then checks it as a concrete rule); otherwise the exit code (0 all accepted, 1 a rule rejected).
// Bad input throws gmr::Error (exit 2).
std::optional<int> check_scheme_input(const std::string& path, bool json, bool algorithm3_strict,
                                      bool embeddings = true);

}  // namespace gmr::cli
