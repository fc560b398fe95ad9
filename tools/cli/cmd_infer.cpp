// `gmr infer BEFORE AFTER [--orbit O | --all-orbits] [--map PAIRS.json] [-o DIR] [--json]
//  [--explicit-loops 2] [--prior-cut-loops 1,2] [--cut-loops 1,2] [--all-relabelings]`: rule
//  inference by topological folding (thesis Ch. 7, inference/infer.hpp).
// The preserved darts are given by a gmr.mapping file (--map: dart pairs and orbit pairs,
// inference/dart_mapping.hpp) or, by default, by identity on dart ids (darts alive in both maps).
// Without --orbit every orbit type is tried (progress on standard error when it is a terminal).
// Prints the summary table (orbit type, start dart, nodes in L and R, outcome: fold failure by
// name, checker verdict, duplicates merged) or, with --json, the same as JSON with the accepted
// schemes. With -o DIR, writes atomically for every accepted rule k: DIR/rule_k.json (gmr.rule
// scheme) and DIR/rule_k.dot and .svg (diagram, rendered by Graphviz), for every rule the checker
// rejected: DIR/rejected_k.json and DIR/rejected_k.dot/.svg (diagnostics highlighted), and
// DIR/summary.txt. Schemes of more than kMaxDrawnNodes nodes get no SVG (the summary says so).
// Exit 0 when at least one rule is inferred, 1 when none is, 2 on bad input.
#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <memory>

#include "checker/check_format.hpp"
#include "checker/dot_overlay.hpp"
#include "inference/dart_mapping.hpp"
#include "inference/infer.hpp"
#include "inference/inference_format.hpp"
#include "inference/prior_cut.hpp"
#include "model/core/error.hpp"
#include "model/draw/render.hpp"
#include "model/draw/rule_dot.hpp"
#include "model/map_io/atomic_write.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "tools/cli/cli.hpp"
#include "tools/cli/inference_args.hpp"
#include "tools/cli/subcommand.hpp"

namespace gmr::cli {

using namespace gmr::checker;
using namespace gmr::draw;
using namespace gmr::io;
using namespace gmr::scheme;

namespace {

// Larger schemes (e.g. an inferred second Menger iteration, 400+ nodes) are left as DOT only:
// Graphviz lays them out slowly and unreadably.
constexpr size_t kMaxDrawnNodes = 300;

struct InferArgs {
  std::string before, after, from, orbit, map, output, explicit_loops, prior_cut_loops, cut_loops;
  bool all_orbits = false, json = false, all_relabelings = false;
};

int run_infer(const InferArgs& a) {
  using namespace gmr::inference;
  if (!a.orbit.empty() && a.all_orbits)
    throw Error(ErrorCode::Usage, "give either --orbit or --all-orbits", "--all-orbits");
  const EmbeddedMap g = load_map(a.before, a.from), h = load_map(a.after, a.from);
  const DartMapping m = a.map.empty() ? identity_mapping(g.map, h.map) : read_mapping_file(a.map);
  JointGraph j(0);
  try {
    j = joint_from_pair(g.map, h.map, m);
  } catch (const Error& e) {
    if (e.code() != ErrorCode::Schema || a.map.empty()) throw;
    throw Error(ErrorCode::Schema, e.message(), a.map + ":$." + e.location());
  }
  cut_prior_loops(j,
                  parse_dimension_list(a.prior_cut_loops, g.map.dimension(), "--prior-cut-loops"));
  InferOptions opt;
  if (!a.orbit.empty()) opt.orbit = parse_orbit_option(a.orbit, "--orbit");
  opt.fold.loops.explicit_loops =
      parse_dimension_list(a.explicit_loops, g.map.dimension(), "--explicit-loops");
  opt.all_relabelings = a.all_relabelings;
  opt.rule.cut_loops = parse_dimension_list(a.cut_loops, g.map.dimension(), "--cut-loops");
  const bool tty = isatty(STDERR_FILENO) != 0;
  if (tty && !opt.orbit)
    opt.progress = [](size_t k, size_t n, const OrbitType& o) {
      std::cerr << "\rgmr infer: orbit type " << k << "/" << n << " " << o.str() << "        "
                << std::flush;
      if (k == n) std::cerr << "\n";
    };
  const InferenceResult res = infer_rules(j, opt);
  const std::string summary = to_text(res);
  if (a.json) {
    nlohmann::ordered_json out;
    out["before"] = a.before;
    out["after"] = a.after;
    out["mapping"] = a.map.empty() ? "identity" : a.map;
    nlohmann::ordered_json attempts = nlohmann::ordered_json::array();
    for (const auto& at : res.attempts) {
      nlohmann::ordered_json x{{"orbit", at.orbit.str()},
                               {"start", at.start_text},
                               {"outcome", to_string(at.outcome)},
                               {"left_nodes", at.left_nodes},
                               {"right_nodes", at.right_nodes}};
      if (at.outcome == AttemptOutcome::FoldFailed) x["failure"] = to_json(at.failure, j);
      if (at.rule >= 0) x["rule"] = at.rule;
      if (at.rejected) {
        x["reason"] = at.reason;
        if (at.outcome == AttemptOutcome::Inconsistent) x["check"] = to_json(at.rejected->check);
      }
      attempts.push_back(x);
    }
    out["attempts"] = attempts;
    nlohmann::ordered_json rules = nlohmann::ordered_json::array();
    for (size_t k = 0; k < res.rules.size(); ++k)
      rules.push_back({{"duplicates_merged", res.duplicates[k]},
                       {"scheme", scheme_to_json(res.rules[k].scheme)}});
    out["rules"] = rules;
    print_json(out);
  } else {
    std::cout << summary;
  }
  if (!a.output.empty()) {
    const std::filesystem::path dir(a.output);
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw Error(ErrorCode::Io, "cannot create the directory: " + ec.message(), a.output);
    std::string not_drawn;
    // The diagram as DOT, and as SVG (Graphviz) unless the scheme is too large to lay out usefully.
    auto write_diagram = [&](const RuleScheme& s, const std::string& base, const std::string& dot) {
      write_file_atomic(dir / (base + ".dot"), dot);
      const size_t nodes = s.left.size() + s.right.size();
      if (nodes <= kMaxDrawnNodes)
        draw::render_dot_file(dot, draw::ImageFormat::Svg, dir / (base + ".svg"));
      else
        not_drawn += base + ".svg not drawn: " + std::to_string(nodes) + " nodes (more than " +
                     std::to_string(kMaxDrawnNodes) + "; " + base + ".dot has the diagram)\n";
    };
    for (size_t k = 0; k < res.rules.size(); ++k) {
      const std::string base = "rule_" + std::to_string(k);
      write_scheme_file(res.rules[k].scheme, dir / (base + ".json"));
      write_diagram(res.rules[k].scheme, base, to_dot(res.rules[k].scheme));
    }
    size_t r = 0;
    for (const auto& at : res.attempts) {
      if (!at.rejected) continue;
      RuleScheme s = at.rejected->scheme;
      s.name = "rejected_" + std::to_string(r);
      s.description += " Not a rule: " + at.reason;
      const std::string base = "rejected_" + std::to_string(r++);
      write_scheme_file(s, dir / (base + ".json"));
      RuleDotOptions dot;
      if (at.outcome == AttemptOutcome::Inconsistent)
        dot.highlights = dot_highlights(at.rejected->check);
      write_diagram(s, base, to_dot(s, dot));
    }
    write_file_atomic(dir / "summary.txt", summary + not_drawn);
  }
  return res.rules.empty() ? kExitNegative : kExitOk;
}

}  // namespace

void register_infer(CLI::App& app) {
  auto [sub, args] =
      add_subcommand<InferArgs>(app, "infer",
                                "Infer rule schemes from a before and an after map by topological "
                                "folding (thesis Ch. 7); exit 1 if none is found",
                                run_infer);
  sub->add_option("before", args->before, "Before map (.json, .off, .obj)")->required();
  sub->add_option("after", args->after, "After map (.json, .off, .obj)")->required();
  sub->add_option("--from", args->from,
                  std::string("Input format of both maps (") + kInputFormats + ")");
  sub->add_option("--orbit", args->orbit,
                  "Orbit type to fold on, e.g. \"<0,1,2>\" (default: every orbit type)");
  sub->add_flag("--all-orbits", args->all_orbits, "Try every orbit type (2^(n+1)), the default");
  sub->add_option(
      "--map", args->map,
      "Preserved darts: gmr.mapping file (dart pairs, orbit pairs); default identity on dart ids");
  sub->add_option("--explicit-loops", args->explicit_loops,
                  "Dimensions whose loops are always explicit arcs (conservative), e.g. 2 or 0,2 "
                  "(default: implicit first)");
  sub->add_flag("--all-relabelings", args->all_relabelings,
                "Fold every combination of consistent relabelings (thesis §7.6), not only the "
                "documented default choice");
  sub->add_option("--prior-cut-loops", args->prior_cut_loops,
                  "Prior-cut loops: before folding, remove loops of these dimensions that a "
                  "preserved dart has before and after, e.g. 2");
  sub->add_option("--cut-loops", args->cut_loops,
                  "Posterior-cut loops: remove explicit loops of these dimensions present on both "
                  "copies of a preserved node, e.g. 2");
  sub->add_option("-o,--output", args->output,
                  "Directory for rule_k.json/.dot/.svg, rejected_k.json/.dot/.svg and summary.txt");
  add_json_flag(sub, args->json, "Print JSON (attempts and inferred schemes)");
}

}  // namespace gmr::cli
