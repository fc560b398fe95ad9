// `gmr dot FILE [-o OUT]`: the drawing of a map (model/io_dot.hpp): DOT text on standard output,
// or DOT/SVG/PNG written atomically to OUT (format by extension or --to).
#include <iostream>
#include <memory>

#include "tools/cli/cli.hpp"

namespace gmr::cli {

namespace {

struct DotArgs {
  std::string input, from, output = "-", to;
  bool loops = false;
  std::string name = "gmap";
};

int run_dot(const DotArgs& a) {
  const Format out = a.output == "-" && a.to.empty() ? Format::Dot : output_format(a.output, a.to);
  if (out != Format::Dot && out != Format::Svg && out != Format::Png)
    throw Error(ErrorCode::Usage, std::string("gmr dot writes dot, svg or png, not ") + to_string(out), a.output);
  const GMapFile f = load_map(a.input, a.from);
  DotOptions opt;
  opt.loops = a.loops;
  opt.name = a.name;
  save_map(f, a.output, out, opt);
  return kExitOk;
}

}  // namespace

void register_dot(CLI::App& app) {
  auto args = std::make_shared<DotArgs>();
  CLI::App* sub = app.add_subcommand(
      "dot", "Draw a map: darts as nodes, links coloured per dimension (0 black, 1 red, 2 blue, 3 green, "
             "4 orange, 5 purple, 6 brown, 7 cyan)");
  sub->add_option("file", args->input, "Map file (.json, .off; - for standard input with --from)")->required();
  sub->add_option("--from", args->from, std::string("Input format (") + kInputFormats + ")");
  sub->add_option("-o,--output", args->output, "Output file (.dot, .svg, .png); default: DOT on standard output");
  sub->add_option("--to", args->to, "Output format (dot|svg|png)");
  sub->add_flag("--loops", args->loops, "Draw the i-loops of free darts");
  sub->add_option("--name", args->name, "Graph name")->capture_default_str();
  set_action(sub, [args] { return run_dot(*args); });
}

}  // namespace gmr::cli
