// The `gmr` command line: one binary, one subcommand per file
// tools/cli/cmd_<name>.cpp, each exposing `void register_<name>(CLI::App&)` that adds the
// subcommand, its options and its action (cli.hpp: set_action).
//
// Exit codes: 0 success, 1 negative verdict, 2 bad input or usage. Errors are printed as
// "gmr: error: <location>: <message>" on standard error.
#include <iostream>

#include <CLI/CLI.hpp>

#include "model/core/error.hpp"
#include "tools/cli/cli.hpp"

// ===== SUBCOMMAND REGISTRATION LIST =====================================================
// To add a subcommand: write tools/cli/cmd_<name>.cpp defining
//   namespace gmr::cli { void register_<name>(CLI::App& app); }
// and add one line `X(<name>)` here (the file is picked up by tools/CMakeLists.txt).
#define GMR_SUBCOMMANDS(X) \
  X(info)                  \
  X(validate)              \
  X(convert)               \
  X(dot)                   \
  X(signature)             \
  X(check)                 \
  X(apply)                 \
  X(fold)                  \
  X(infer)                 \
  X(demo)                  \
  X(verify)                \
  X(validate_condition)
// ========================================================================================

namespace gmr::cli {

#define GMR_DECLARE_SUBCOMMAND(name) void register_##name(CLI::App& app);
GMR_SUBCOMMANDS(GMR_DECLARE_SUBCOMMAND)
#undef GMR_DECLARE_SUBCOMMAND
}  // namespace gmr::cli

int main(int argc, char** argv) {
  CLI::App app{"gmr: rule-based topological modeling on generalized maps", "gmr"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("gmr ") + GMR_VERSION);
#define GMR_REGISTER_SUBCOMMAND(name) gmr::cli::register_##name(app);
  GMR_SUBCOMMANDS(GMR_REGISTER_SUBCOMMAND)
#undef GMR_REGISTER_SUBCOMMAND
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);  // --help, --version
    std::cerr << "gmr: error: usage: " << e.what() << "\n"
              << "Run 'gmr --help' or 'gmr <command> --help' for more information.\n";
    return gmr::cli::kExitBadInput;
  } catch (const gmr::Error& e) {
    std::cerr << "gmr: error: " << (e.location().empty() ? "" : e.location() + ": ") << e.message() << "\n";
    return gmr::cli::kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "gmr: error: " << e.what() << "\n";
    return gmr::cli::kExitBadInput;
  }
  return gmr::cli::exit_code();
}
