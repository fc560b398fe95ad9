// The registration of a `gmr` subcommand (tools/cli/cmd_*.cpp): its arguments, its action and the
// options most subcommands share (a map file with --from, --json).
#pragma once
#include <CLI/CLI.hpp>
#include <memory>
#include <string>
#include <utility>

#include "tools/cli/cli.hpp"

namespace gmr::cli {

// Help text of a map file argument that may be standard input.
inline constexpr const char* kMapFileHelp =
    "Map file (.json, .off, .obj; - for standard input with --from)";

// Adds subcommand `name` to `app` with fresh arguments and the action `run`, whose result becomes
// the exit code (set_action). The options of the subcommand are bound to the returned arguments.
template <class Args>
std::pair<CLI::App*, std::shared_ptr<Args>> add_subcommand(CLI::App& app, const std::string& name,
                                                           const std::string& description,
                                                           int (*run)(const Args&)) {
  auto args = std::make_shared<Args>();
  CLI::App* sub = app.add_subcommand(name, description);
  set_action(sub, [args, run] { return run(*args); });
  return {sub, args};
}

// The required map file argument `name` and its --from option (cli.hpp: input_format).
void add_map_input(CLI::App* sub, std::string& input, std::string& from,
                   const std::string& name = "file", const std::string& help = kMapFileHelp);

// The --json flag.
void add_json_flag(CLI::App* sub, bool& json, const std::string& help = "Print JSON");

}  // namespace gmr::cli
