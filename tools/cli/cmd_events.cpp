// `gmr events RULE [--orbits "<0,1>,<1,2>"] [--rule NAME] [--json]`: the static events of a rule
// scheme (checker/events/static_events.hpp) for every orbit type of its dimension, or those given:
// per orbit type, each creation, deletion, split, merge, modification or non-modification of a
// pattern orbit, certain or possible with the instance pairs to compare at application time. A
// Jerboa .jme file gives one table per rule (or the rule named by --rule). A concrete rule is
// analysed as its scheme on <> (checker/events/concrete_scheme.hpp: one dart per node). Exit 0, 2
// on bad input.
#include <filesystem>
#include <iostream>
#include <memory>

#include "checker/events/concrete_scheme.hpp"
#include "checker/events/event_format.hpp"
#include "model/core/error.hpp"
#include "model/map_io/json_writer.hpp"
#include "model/rule_io/jme_import.hpp"
#include "tools/cli/cli.hpp"
#include "tools/cli/orbit_list.hpp"
#include "tools/cli/rule_input.hpp"
#include "tools/cli/subcommand.hpp"

namespace gmr::cli {
using namespace gmr::events;

namespace {

struct EventsArgs {
  std::string rule, orbits, rule_name;
  bool json = false;
};

std::vector<RuleScheme> load_schemes(const EventsArgs& a) {
  if (std::filesystem::path(a.rule).extension() == ".jme" && a.rule_name.empty()) {
    io::JmeModeler m = io::read_jme_file(a.rule);
    if (m.rules.empty()) throw Error(ErrorCode::Schema, "the Jerboa file has no rule", a.rule);
    return std::move(m.rules);
  }
  RuleInput in = load_rule_input(a.rule, a.rule_name);
  if (!in.is_scheme()) return {scheme_of_concrete_rule(*in.concrete)};
  return {std::move(*in.scheme)};
}

int run_events(const EventsArgs& a) {
  const std::vector<OrbitType> types = parse_orbit_list(a.orbits);
  const std::vector<RuleScheme> schemes = load_schemes(a);
  nlohmann::ordered_json docs = nlohmann::ordered_json::array();
  std::string text;
  for (const RuleScheme& s : schemes) {
    if (schemes.size() == 1) {
      const StaticEvents st = analyse(s, types);  // errors: exit 2
      docs.push_back(static_events_to_json(s, st));
      text += static_events_to_text(s, st);
      continue;
    }
    try {
      const StaticEvents st = analyse(s, types);
      docs.push_back(static_events_to_json(s, st));
      text += static_events_to_text(s, st) + "\n";
    } catch (const Error& e) {
      docs.push_back({{"rule", s.name},
                      {"error", (e.location().empty() ? "" : e.location() + ": ") + e.message()}});
      text += s.name + ": not analysed: " + e.message() + "\n\n";
    }
  }
  if (!a.json) {
    std::cout << text;
  } else if (docs.size() == 1) {
    print_json(docs[0]);
  } else {
    nlohmann::ordered_json j;
    j["format"] = kEventsFormat;
    j["version"] = kEventsVersion;
    j["kind"] = "static-set";
    j["file"] = a.rule;
    j["rules"] = docs;
    print_json(j);
  }
  return kExitOk;
}

}  // namespace

void register_events(CLI::App& app) {
  auto [sub, args] = add_subcommand<EventsArgs>(
      app, "events",
      "Static topological events of a rule scheme per orbit type: creation, deletion, split, "
      "merge, modification, certain or to confirm",
      run_events);
  sub->add_option("rule", args->rule,
                  "Rule (gmr.rule JSON, scheme or concrete: a scheme on <>) or Jerboa .jme file "
                  "(every rule)")
      ->required();
  sub->add_option("--orbits", args->orbits,
                  "Orbit types to analyse, e.g. \"<0,1>,<1,2>\" (default: all 2^(n+1))");
  sub->add_option("--rule", args->rule_name, "The rule of a .jme file (default: every rule)");
  add_json_flag(sub, args->json, "Print JSON (format gmr.events, kind static)");
}

}  // namespace gmr::cli
