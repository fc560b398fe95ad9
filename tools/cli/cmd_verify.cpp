// `gmr verify RULE --bound k [--engine smt|enum|both] [--json] [-o cex.json] [--dot cex.dot]`:
// bounded verification of a concrete rule or a rule scheme (checker/smt/rule_verifier.hpp,
// scheme_verifier.hpp; docs/verify.md). Either "no map of the model with at most k darts on which
// an application breaks a constraint" (bound, engine, time), or a counterexample (G, the match, H,
// the broken constraints) written as JSON (gmr.counterexample) and DOT. Exit 0 when the rule
// preserves the model within the bound, 1 when a counterexample exists, 2 on bad input.
#include <iostream>
#include <memory>
#include <sstream>

#include "checker/smt/counterexample.hpp"
#include "model/core/error.hpp"
#include "tools/cli/cli.hpp"
#include "tools/cli/rule_input.hpp"
#include "tools/cli/subcommand.hpp"

namespace gmr::cli {
using namespace gmr::smt;

namespace {

struct VerifyArgs {
  std::string input;
  std::string rule_name;
  unsigned bound = 6;
  unsigned orbit_bound = 0;
  std::string engine = "smt";
  bool json = false;
  std::string output;
  std::string dot;
};

struct Run {
  VerifyResult result;
  std::optional<SchemeVerifyResult> scheme;
  std::optional<Rule> concrete;
  // The concrete rule the counterexample belongs to (the instance, for a scheme).
  const Rule& rule() const { return scheme && scheme->instance ? *scheme->instance : *concrete; }
};

std::string model_name(const Rule& r) {
  return std::to_string(r.dimension()) + "-" + (r.kind() == MapKind::OMap ? "O-map" : "G-map");
}

std::string describe(const Rule& r, const Counterexample& c) {
  std::ostringstream s;
  s << "counterexample on a " << model_name(r) << " of " << c.G.size() << " darts; match";
  for (graph::Node v : r.left().nodes()) s << " " << r.left().name(v) << "->" << c.match.node[v];
  s << "; H breaks";
  for (size_t k = 0; k < c.violations.size() && k < 4; ++k)
    s << (k ? "; " : " ") << graph::to_text(c.violations[k], c.H);
  if (c.violations.size() > 4) s << "; ... (" << c.violations.size() << " in all)";
  return s.str();
}

int run_verify(const VerifyArgs& a) {
  if (a.bound < 1 || a.bound > 16)
    throw Error(ErrorCode::Usage, "--bound must be in 1..16", "--bound");
  // The drawing's format, from its extension, before the sweep.
  const Format dot_format = a.dot.empty() ? Format::Dot : drawing_format(a.dot, "");
  std::vector<Engine> engines;
  if (a.engine == "smt" || a.engine == "both") engines.push_back(Engine::Smt);
  if (a.engine == "enum" || a.engine == "both") engines.push_back(Engine::Enum);
  if (engines.empty())
    throw Error(ErrorCode::Usage, "unknown engine '" + a.engine + "' (smt|enum|both)", "--engine");
  RuleInput in = load_rule_input(a.input, a.rule_name);
  const std::string name = in.is_scheme() ? in.scheme->name : in.concrete->name();
  std::vector<Run> runs;
  for (Engine e : engines) {
    Run run;
    if (in.is_scheme()) {
      run.scheme = verify_scheme(*in.scheme, a.bound, e, a.orbit_bound);
      if (run.scheme->result) {
        run.result = *run.scheme->result;
      } else {
        run.result.engine = e;
        run.result.bound = a.bound;
        run.result.applicable = run.scheme->applicable > 0;
      }
      run.result.seconds = run.scheme->seconds;
    } else {
      run.result = verify(*in.concrete, a.bound, e);
      run.concrete = *in.concrete;
    }
    runs.push_back(std::move(run));
  }
  const Run& first = runs.front();
  for (const Run& r : runs)
    if (r.result.preserves != first.result.preserves)
      throw std::logic_error("the engines disagree on " + name + " (smt " +
                             (runs[0].result.preserves ? "preserves" : "breaks") + ", enum " +
                             (runs[1].result.preserves ? "preserves" : "breaks") + ")");
  const Run* cex = nullptr;
  for (const Run& r : runs)
    if (r.result.counterexample && !cex) cex = &r;
  if (cex) {
    const auto& c = *cex->result.counterexample;
    if (!a.output.empty()) write_output(a.output, to_json(cex->rule(), a.bound, c).dump(2) + "\n");
    if (!a.dot.empty()) write_drawing(a.dot, to_dot(cex->rule(), c), dot_format);
  }
  if (a.json) {
    nlohmann::ordered_json j;
    j["format"] = "gmr.verify";
    j["version"] = 1;
    j["file"] = a.input;
    j["rule"] = name;
    j["kind"] = in.is_scheme() ? "scheme" : "concrete";
    j["bound"] = a.bound;
    j["verdict"] = first.result.preserves ? "preserves" : "breaks";
    j["engines"] = nlohmann::ordered_json::array();
    for (const Run& r : runs) {
      auto e = verdict_json(r.result);
      if (r.scheme) {
        e["orbit_bound"] = r.scheme->orbit_bound;
        e["orbits"] = r.scheme->orbits;
        e["applicable_orbits"] = r.scheme->applicable;
      }
      j["engines"].push_back(e);
    }
    if (cex) {
      auto cj = to_json(cex->rule(), a.bound, *cex->result.counterexample);
      if (cex->scheme) cj["instance_of"] = name;
      j["counterexample"] = cj;
    }
    print_json(j);
  } else {
    for (const Run& r : runs) {
      std::cout << name << ": ";
      const std::string model = in.is_scheme() ? std::to_string(in.scheme->dimension) + "-G-map"
                                               : model_name(*in.concrete);
      if (r.result.preserves)
        std::cout << "no " << model << " of at most " << a.bound
                  << " darts on which an application breaks a constraint"
                  << (r.result.applicable ? "" : " (the rule never applies within the bound)");
      else
        std::cout << describe(r.rule(), *r.result.counterexample);
      if (r.scheme)
        std::cout << " [" << r.scheme->orbits << " hook orbits of at most " << r.scheme->orbit_bound
                  << " darts]";
      std::printf(" (engine %s, %.3f s)\n", to_string(r.result.engine), r.result.seconds);
      std::cout.flush();
    }
  }
  return first.result.preserves ? kExitOk : kExitNegative;
}

}  // namespace

void register_verify(CLI::App& app) {
  auto [sub, args] =
      add_subcommand<VerifyArgs>(app, "verify",
                                 "Bounded verification of a rule: does any application on a map of "
                                 "at most k darts break a constraint? Exit 1 with a counterexample",
                                 run_verify);
  sub->add_option("rule", args->input,
                  "Rule file (gmr.rule JSON, concrete or scheme) or Jerboa .jme file")
      ->required();
  sub->add_option("--rule", args->rule_name, "Rule of a .jme file");
  sub->add_option("--bound,-k", args->bound, "Maps of at most this many darts (default 6)");
  sub->add_option("--orbit-bound", args->orbit_bound,
                  "Rule schemes: instantiate on hook orbits of at most this many darts only "
                  "(default: the bound)");
  sub->add_option("--engine", args->engine,
                  "smt (Z3, default), enum (exhaustive enumeration) or both");
  add_json_flag(sub, args->json, "Print JSON (format gmr.verify)");
  sub->add_option("-o,--output", args->output,
                  "Write the counterexample (gmr.counterexample JSON)");
  sub->add_option("--dot", args->dot,
                  "Write the counterexample's G, offending darts highlighted: DOT, or SVG/PNG by "
                  "the file's extension");
}

}  // namespace gmr::cli
