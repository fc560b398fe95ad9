// `gmr convert IN OUT`: map file conversion. Input json|off, output json|off|obj|dot|svg|png, by
// extension or --from/--to. OFF/OBJ output needs a 2-G-map with a "position" embedding.
#include <iostream>
#include <memory>

#include "tools/cli/cli.hpp"
#include "tools/cli/subcommand.hpp"

namespace gmr::cli {
using namespace gmr::draw;

namespace {

struct ConvertArgs {
  std::string input, output, from, to;
  bool loops = false;
};

int run_convert(const ConvertArgs& a) {
  const Format out = output_format(a.output, a.to);
  const EmbeddedMap f = load_map(a.input, a.from);
  DotOptions dot;
  dot.loops = a.loops;
  save_map(f, a.output, out, dot);
  return kExitOk;
}

}  // namespace

void register_convert(CLI::App& app) {
  auto [sub, args] = add_subcommand<ConvertArgs>(
      app, "convert", "Convert a map file (json, off -> json, off, obj, dot, svg, png)",
      run_convert);
  sub->add_option("input", args->input, "Input file (- for standard input with --from)")
      ->required();
  sub->add_option("output", args->output,
                  "Output file, written atomically (- for standard output with --to)")
      ->required();
  sub->add_option("--from", args->from, std::string("Input format (") + kInputFormats + ")");
  sub->add_option("--to", args->to, std::string("Output format (") + kOutputFormats + ")");
  sub->add_flag("--loops", args->loops, "Draw i-loops of free darts (dot, svg, png)");
}

}  // namespace gmr::cli
