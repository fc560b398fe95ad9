// `gmr validate-condition (--condition NAME | --plugin LIB.so) [--model gmap|omap] [-n N]
//  [--labels 0,1] [--max-nodes m] [--random N --seed S] [--bound k] [--engine smt|enum|symbolic]
//  [--shard K/M] [--time-limit s]
//  [--eval-timeout s] [--schemes FILE...] [--json] [-o report.json]` | `--merge shard1.json
//  shard2.json ...`: is the condition sound and complete against the DPO semantics on
// every rule of the bounded family and every map of at most k darts
// (checker/smt/condition_validation.hpp; docs/verify.md)? Built-in conditions run in-process,
// plug-ins in a forked child (checker/smt/condition_plugin.hpp). Progress on standard error when
// it is a terminal. Exit 0 when sound and complete within the bounds, 1 otherwise, 2 on bad input
// (a plug-in that fails to load, lacks its entry symbol, throws or crashes).
#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

#include "checker/smt/condition_plugin.hpp"
#include "checker/smt/condition_registry.hpp"
#include "checker/smt/condition_validation.hpp"
#include "checker/smt/counterexample.hpp"
#include "checker/smt/scheme_conditions.hpp"
#include "checker/smt/symbolic_validation.hpp"
#include "checker/smt/validation_format.hpp"
#include "model/core/error.hpp"
#include "model/map_io/read_file.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "tools/cli/cli.hpp"
#include "tools/cli/subcommand.hpp"

namespace gmr::cli {
using namespace gmr::smt;

namespace {

struct ValidateConditionArgs {
  std::string condition;
  std::string plugin;
  bool list = false;
  std::string model = "gmap";
  int n = -1;
  std::string labels;
  int max_nodes = 2;
  unsigned bound = 4;
  std::string engine = "smt";
  std::string shard = "0/1";
  double time_limit = 0;
  bool json = false;
  std::string output;
  std::vector<std::string> merge;
  size_t random = 0;
  uint64_t seed = 1;
  double eval_timeout = ConditionPlugin::kDefaultEvalTimeout;
  std::vector<std::string> schemes;
};

std::vector<int> parse_labels(const std::string& text) {
  std::vector<int> out;
  std::stringstream s(text);
  std::string item;
  while (std::getline(s, item, ',')) {
    try {
      size_t used = 0;
      out.push_back(std::stoi(item, &used));
      if (used != item.size()) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw Error(ErrorCode::Usage, "not a label list: '" + text + "'", "--labels");
    }
  }
  return out;
}

// Writes a validation report (-o, --json or text) and returns the exit code: 0 when sound and
// complete.
template <class Report>
int report(const ValidateConditionArgs& a, const Report& rep) {
  const auto j = to_json(rep);
  if (!a.output.empty()) write_output(a.output, j.dump(2) + "\n");
  if (a.json)
    print_json(j);
  else
    std::cout << to_text(rep);
  return rep.sound() && rep.complete() ? kExitOk : kExitNegative;
}

// --engine symbolic: one query per direction for the whole family (symbolic_validation.hpp).
int run_symbolic(const ValidateConditionArgs& a, ValidationOptions o) {
  if (!a.plugin.empty())
    throw Error(ErrorCode::Usage, "plug-ins are evaluated rule by rule (engines smt and enum)",
                "--engine symbolic");
  if (!find_builtin_condition(a.condition))
    throw Error(ErrorCode::Usage, "unknown condition '" + a.condition + "' (--list: the names)",
                "--condition");
  o.progress = nullptr;
  const SymbolicReport rep = validate_symbolic(a.condition, o);
  return report(a, rep);
}

// A scheme condition (scheme_conditions.hpp; built in, or a plug-in's optional entry point) on the
// schemes of --schemes, through instantiation.
int run_scheme_condition(const ValidateConditionArgs& a, const SchemeCondition* builtin,
                         const ConditionPlugin* plugin) {
  const std::string name = builtin ? builtin->name : plugin->scheme_name();
  if (a.schemes.empty())
    throw Error(ErrorCode::Usage,
                "a scheme condition needs the schemes to validate it on (--schemes FILE...)",
                builtin ? "--condition " + name : "--plugin " + a.plugin);
  if (a.bound < 1 || a.bound > 8)
    throw Error(ErrorCode::Usage, "must be in 1..8 for schemes", "--bound");
  std::vector<RuleScheme> schemes;
  for (const auto& f : a.schemes) schemes.push_back(io::read_scheme_file(f));
  const bool sufficient_only = builtin && builtin->sufficient_only;
  const SchemeValidationReport r =
      builtin ? validate_scheme_condition(*builtin, schemes, a.bound)
              : validate_scheme_condition(name, plugin->evaluate_schemes(schemes, a.eval_timeout),
                                          schemes, a.bound);
  const nlohmann::ordered_json j = to_json(r, sufficient_only);
  if (!a.output.empty()) write_output(a.output, j.dump(2) + "\n");
  if (a.json)
    print_json(j);
  else
    std::cout << to_text(r);
  // A sufficient-only condition is refuted by unsoundness alone.
  return r.sound() && (sufficient_only || r.complete()) ? kExitOk : kExitNegative;
}

int run_validate_condition(const ValidateConditionArgs& a) {
  if (a.list) {
    for (const auto& c : builtin_conditions())
      std::printf("%-32s %s\n", c.name.c_str(), c.description.c_str());
    for (const auto& c : builtin_scheme_conditions())
      std::printf("%-32s %s (schemes: --schemes FILE...)\n", c.name.c_str(), c.description.c_str());
    return kExitOk;
  }
  if (!a.condition.empty())
    if (const SchemeCondition* sc = find_builtin_scheme_condition(a.condition))
      return run_scheme_condition(a, sc, nullptr);
  if (!a.plugin.empty() && !a.schemes.empty()) {
    ConditionPlugin plugin(a.plugin);
    if (!plugin.judges_schemes())
      throw Error(ErrorCode::Usage,
                  std::string("the plug-in has no ") + kSchemeConditionEntrySymbol +
                      ": it judges concrete rules (drop --schemes)",
                  "plugin " + a.plugin);
    return run_scheme_condition(a, nullptr, &plugin);
  }
  if (!a.schemes.empty())
    throw Error(ErrorCode::Usage, "--schemes goes with a scheme condition (--list)", "--schemes");
  if (!a.merge.empty()) {
    std::vector<nlohmann::json> docs;
    for (const auto& f : a.merge) {
      try {
        docs.push_back(nlohmann::json::parse(io::read_text_file(f)));
      } catch (const nlohmann::json::exception& e) {
        throw Error(ErrorCode::Parse, e.what(), f);
      }
    }
    const auto j = merge_reports(docs);
    if (!a.output.empty()) write_output(a.output, j.dump(2) + "\n");
    print_json(j);
    return j["sound"].get<bool>() && j["complete"].get<bool>() ? kExitOk : kExitNegative;
  }
  if (a.condition.empty() == a.plugin.empty())
    throw Error(ErrorCode::Usage,
                "give exactly one of --condition NAME and --plugin LIB.so (--list: the names)",
                "validate-condition");
  ValidationOptions o;
  if (a.model != "gmap" && a.model != "omap")
    throw Error(ErrorCode::Usage, "gmap or omap", "--model");
  o.kind = a.model == "omap" ? MapKind::OMap : MapKind::GMap;
  o.labels = a.labels.empty() ? std::vector<int>{} : parse_labels(a.labels);
  int max_label = o.labels.empty() ? -1 : *std::max_element(o.labels.begin(), o.labels.end());
  o.n = a.n >= 0 ? a.n : std::max(max_label, o.kind == MapKind::OMap ? 2 : 1);
  const MapSpec spec{o.n, o.kind};
  if (a.labels.empty()) o.labels = spec.labels();
  for (int i : o.labels)
    if (!spec.has_dim(i))
      throw Error(ErrorCode::Usage, "label " + std::to_string(i) + " is not a label of the model",
                  "--labels");
  if (a.max_nodes < 1 || a.max_nodes > 4)
    throw Error(ErrorCode::Usage, "must be in 1..4", "--max-nodes");
  if (a.bound < 1 || a.bound > 12) throw Error(ErrorCode::Usage, "must be in 1..12", "--bound");
  o.max_nodes = a.max_nodes;
  o.bound = a.bound;
  if (a.engine != "smt" && a.engine != "enum" && a.engine != "symbolic")
    throw Error(ErrorCode::Usage, "smt, enum or symbolic", "--engine");
  o.engine = a.engine == "enum" ? Engine::Enum : Engine::Smt;
  unsigned k = 0, m = 0;
  char slash = 0;
  std::istringstream ss(a.shard);
  if (!(ss >> k >> slash >> m) || slash != '/' || m == 0 || k >= m || !ss.eof())
    throw Error(ErrorCode::Usage, "expected K/M with 0 <= K < M", "--shard");
  o.shard = k;
  o.shards = m;
  o.time_limit = a.time_limit;
  if (!(a.eval_timeout >= 0))
    throw Error(ErrorCode::Usage, "must be a number of seconds >= 0", "--eval-timeout");
  o.random = a.random;
  o.seed = a.seed;
  if (isatty(STDERR_FILENO))
    o.progress = [](size_t done, size_t total) {
      std::fprintf(stderr, "\r  %zu / %zu rules", done, total);
      if (done == total) std::fprintf(stderr, "\n");
    };
  if (a.engine == "symbolic") return run_symbolic(a, o);
  ValidationReport rep;
  if (!a.plugin.empty()) {
    ConditionPlugin plugin(a.plugin);
    rep = validate_condition(
        plugin.name(),
        [&](const std::vector<Rule>& rules) { return plugin.evaluate(rules, a.eval_timeout); }, o);
  } else {
    const BuiltinCondition* c = find_builtin_condition(a.condition);
    if (!c)
      throw Error(ErrorCode::Usage, "unknown condition '" + a.condition + "' (--list: the names)",
                  "--condition");
    rep = validate_condition(*c, o);
  }
  return report(a, rep);
}

}  // namespace

void register_validate_condition(CLI::App& app) {
  auto [sub, args] = add_subcommand<ValidateConditionArgs>(
      app, "validate-condition",
      "Is a condition on concrete rules sound and complete against the DPO semantics (bounded)? "
      "Exit 1 with the smallest counterexamples",
      run_validate_condition);
  sub->add_option("--condition", args->condition, "A built-in condition (--list)");
  sub->add_option("--plugin", args->plugin,
                  "A condition plug-in (shared library exporting gmr_condition_v1)");
  sub->add_flag("--list", args->list, "List the built-in conditions");
  sub->add_option("--model", args->model, "gmap (default) or omap");
  sub->add_option("-n,--dimension", args->n,
                  "Dimension of the model (default: the largest label, at least 1; O-maps 2)");
  sub->add_option("--labels", args->labels,
                  "Labels carrying arcs in the rules, e.g. 0,1 (default: all of the model)");
  sub->add_option("--max-nodes", args->max_nodes,
                  "Rules of at most this many nodes (1..4, default 2)");
  sub->add_option("--bound,-k", args->bound, "Maps of at most this many darts (default 4)");
  sub->add_option(
      "--engine", args->engine,
      "smt (default), enum, or symbolic (every rule of the family in one query per direction; "
      "built-in conditions; the cycle condition through the checker as oracle)");
  sub->add_option("--random", args->random,
                  "Also this many random rules of max-nodes+1 or +2 nodes (default 0)");
  sub->add_option("--seed", args->seed, "Seed of the random rules (default 1)");
  sub->add_option("--shard", args->shard, "K/M: the rules whose index is K mod M (default 0/1)");
  sub->add_option("--time-limit", args->time_limit,
                  "Stop after this many seconds, reporting the part covered");
  sub->add_option("--eval-timeout", args->eval_timeout,
                  "A plug-in's predicate must return within this many seconds per rule (default "
                  "10; 0: no limit)");
  sub->add_option("--schemes", args->schemes,
                  "The rule schemes (gmr.rule JSON files) a scheme condition is validated on, "
                  "through instantiation");
  add_json_flag(sub, args->json, "Print JSON (format gmr.condition-validation)");
  sub->add_option("-o,--output", args->output, "Also write the JSON report to this file");
  sub->add_option("--merge", args->merge,
                  "Merge the JSON reports of the shards of one sweep (prints JSON)");
}

}  // namespace gmr::cli
