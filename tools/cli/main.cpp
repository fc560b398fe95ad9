// The `gmr` command line: one binary, one subcommand per file
// tools/cli/cmd_<name>.cpp, each exposing `void register_<name>(CLI::App&)` that adds the
// subcommand, its options and its action (subcommand.hpp: add_subcommand).
//
// Exit codes: 0 success, 1 negative verdict, 2 bad input or usage. Errors are printed as
// "gmr: error: <location>: <message>" on standard error.
#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstring>
#include <iostream>
#include <new>
#include <string>

#include "model/core/error.hpp"
#include "model/map_io/atomic_write.hpp"
#include "tools/cli/cli.hpp"

// ===== SUBCOMMAND REGISTRATION LIST =====================================================
// To add a subcommand: write tools/cli/cmd_<name>.cpp defining
//   namespace gmr::cli { void register_<name>(CLI::App& app); }
// and add one line `X(<name>)` here (the file is picked up by tools/CMakeLists.txt).
#define GMR_SUBCOMMANDS(X) \
  X(info)                  \
  X(validate)              \
  X(convert)               \
  X(query_replace)         \
  X(patterns)              \
  X(dot)                   \
  X(signature)             \
  X(check)                 \
  X(events)                \
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

namespace {

// The first word on the command line when it is not an option, else empty.
std::string command_word(int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return {};
  return argv[1];
}

bool has_command(CLI::App& app, const std::string& name) {
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (sub->get_name() == name) return true;
  return false;
}

std::string known_commands(CLI::App& app) {
  std::string names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    names += (names.empty() ? "" : ", ") + sub->get_name();
  return names;
}

// Standard output is checked once at exit: a full disk or a closed pipe is a failed command.
int check_standard_output(int code) {
  errno = 0;
  std::cout.flush();
  if (std::cout) return code;
  const int err = errno;
  std::cerr << "gmr: error: standard output: write failed"
            << (err ? std::string(": ") + std::strerror(err) : "") << "\n";
  return gmr::cli::kExitBadInput;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"gmr: rule-based topological modeling on generalized maps", "gmr"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("gmr ") + GMR_VERSION);
#define GMR_REGISTER_SUBCOMMAND(name) gmr::cli::register_##name(app);
  GMR_SUBCOMMANDS(GMR_REGISTER_SUBCOMMAND)
#undef GMR_REGISTER_SUBCOMMAND
  gmr::io::remove_temporaries_on_signal();
  const std::string word = command_word(argc, argv);
  if (word == "help") {  // `gmr help [command]`: the help of gmr or of one command
    if (argc < 3) {
      std::cout << app.help();
      return check_standard_output(gmr::cli::kExitOk);
    }
    argv[1] = argv[2];
    argv[2] = const_cast<char*>("--help");
    argc = 3;
  } else if (!word.empty() && !has_command(app, word)) {
    std::cerr << "gmr: error: usage: unknown command '" << gmr::cli::abbreviate(word)
              << "' (commands: " << known_commands(app) << ")\n";
    return gmr::cli::kExitBadInput;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success))  // --help, --version
      return check_standard_output(app.exit(e));
    std::cerr << "gmr: error: usage: " << gmr::cli::abbreviate(e.what()) << "\n"
              << "Run 'gmr --help' or 'gmr <command> --help' for more information.\n";
    return gmr::cli::kExitBadInput;
  } catch (const gmr::Error& e) {
    std::cerr << "gmr: error: "
              << (e.location().empty() ? "" : gmr::cli::abbreviate(e.location()) + ": ")
              << gmr::cli::abbreviate(e.message()) << "\n";
    return gmr::cli::kExitBadInput;
  } catch (const std::bad_alloc&) {
    std::cerr << "gmr: error: out of memory: the input is too large for this machine\n";
    return gmr::cli::kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "gmr: error: " << gmr::cli::abbreviate(e.what()) << "\n";
    return gmr::cli::kExitBadInput;
  }
  return check_standard_output(gmr::cli::exit_code());
}
