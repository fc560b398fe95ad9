#include "tools/cli/subcommand.hpp"

namespace gmr::cli {

void add_map_input(CLI::App* sub, std::string& input, std::string& from, const std::string& name,
                   const std::string& help) {
  sub->add_option(name, input, help)->required();
  sub->add_option("--from", from, std::string("Input format (") + kInputFormats + ")");
}

void add_json_flag(CLI::App* sub, bool& json, const std::string& help) {
  sub->add_flag("--json", json, help);
}

}  // namespace gmr::cli
