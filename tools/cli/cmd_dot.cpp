// `gmr dot FILE [-o OUT]`: the drawing of a map (model/io_dot.hpp): DOT text on standard output,
// or DOT/SVG/PNG written atomically to OUT (format by extension or --to). Rule files (gmr.rule
// concrete or scheme, Jerboa .jme with --rule NAME) are drawn by rule_dot.hpp (--kappa, --check,
// --events).
#include <iostream>
#include <memory>

#include "tools/cli/cli.hpp"
#include "tools/cli/rule_dot.hpp"
#include "tools/cli/subcommand.hpp"

namespace gmr::cli {
using namespace gmr::draw;

namespace {

struct DotArgs {
  std::string input, from, output = "-", to;
  bool loops = false;
  std::string name = "gmap";
  std::string rule;  // rule files: a rule of a .jme file
  bool kappa = false, check = false;
  size_t max_darts = kMaxRenderedDarts;
  std::string events;  // rule schemes: the orbit type whose static events are drawn
};

int run_dot(const DotArgs& a) {
  if (auto rc = dot_rule_input({a.input, a.output, a.to, a.rule, a.name == "gmap" ? "" : a.name,
                                a.kappa, a.check, a.events}))
    return *rc;
  const Format out = drawing_format(a.output, a.to);
  const EmbeddedMap f = load_map(a.input, a.from);
  DotOptions opt;
  opt.loops = a.loops;
  opt.name = a.name;
  save_map(f, a.output, out, opt, a.max_darts);
  return kExitOk;
}

}  // namespace

void register_dot(CLI::App& app) {
  auto [sub, args] = add_subcommand<DotArgs>(
      app, "dot",
      "Draw a map: darts as nodes, links coloured per dimension (0 black, 1 red, 2 blue, 3 green, "
      "4 orange, 5 purple, 6 brown, 7 cyan)",
      run_dot);
  sub->add_option("file", args->input,
                  "Map file (.json, .off, .obj; - for standard input with --from), or rule file "
                  "(gmr.rule JSON, concrete or "
                  "scheme; Jerboa .jme)")
      ->required();
  sub->add_option("--from", args->from, std::string("Input format (") + kInputFormats + ")");
  sub->add_option("-o,--output", args->output,
                  "Output file (.dot, .svg, .png); default: DOT on standard output");
  sub->add_option("--to", args->to, "Output format (dot|svg|png)");
  sub->add_flag("--loops", args->loops, "Draw the i-loops of free darts");
  sub->add_option("--name", args->name, "Graph name")->capture_default_str();
  sub->add_option("--rule", args->rule, "Rule files: the rule of a .jme file to draw");
  sub->add_flag("--kappa", args->kappa,
                "Concrete rules: draw the kappa arcs of the joint representation (pink dashed)");
  sub->add_flag("--check", args->check,
                "Rule files: run the checker and highlight the offending nodes");
  sub->add_option("--max-darts", args->max_darts,
                  "Largest map rendered to SVG/PNG (Graphviz layout time grows fast)")
      ->check(non_negative_integer())
      ->capture_default_str();
  sub->add_option("--events", args->events,
                  "Rule schemes: highlight the pattern orbits of the static events of this orbit "
                  "type, e.g. \"<0,1>\" "
                  "(possible events orange, certain ones red)");
}

}  // namespace gmr::cli
