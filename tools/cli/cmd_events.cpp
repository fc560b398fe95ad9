// `gmr events RULE [--orbits "<0,1>,<1,2>"] [--rule NAME] [--json]`: the static events of a rule
// scheme (checker/events/static_events.hpp) for every orbit type of its dimension, or those given:
// per orbit type, each creation, deletion, split, merge, modification or non-modification of a
// pattern orbit, certain or possible with the instance pairs to compare at application time. A
// Jerboa .jme file gives one table per rule (or the rule named by --rule). Exit 0, 2 on bad input
// (a concrete rule has no pattern orbits: schemes only).
#include <iostream>
#include <memory>
#include <filesystem>
#include <regex>

#include "checker/events/event_format.hpp"
#include "model/core/error.hpp"
#include "model/io/jme_import.hpp"
#include "model/io/json_writer.hpp"
#include "tools/cli/cli.hpp"
#include "tools/cli/rule_input.hpp"

namespace gmr::cli {
using namespace gmr::events;

namespace {

struct EventsArgs {
  std::string rule, orbits, rule_name;
  bool json = false;
};

// "<0,1>,<1,2>" -> the orbit types (an empty list: all of them).
std::vector<OrbitType> parse_orbit_list(const std::string& text) {
  std::vector<OrbitType> out;
  const std::regex item(R"(\s*(<[^>]*>)\s*(,|$))");
  auto it = text.cbegin();
  std::smatch m;
  while (it != text.cend()) {
    if (!std::regex_search(it, text.cend(), m, item, std::regex_constants::match_continuous))
      throw Error(ErrorCode::Usage, "expected a list of orbit types such as \"<0,1>,<1,2>\", found \"" + text + "\"",
                  "--orbits");
    try {
      out.push_back(OrbitType::parse(m[1].str()));
    } catch (const Error& e) {
      throw Error(e.code(), e.message() + " (" + e.location() + ")", "--orbits");
    }
    it = m[0].second;
  }
  return out;
}

std::vector<RuleScheme> load_schemes(const EventsArgs& a) {
  if (std::filesystem::path(a.rule).extension() == ".jme" && a.rule_name.empty()) {
    io::JmeModeler m = io::read_jme_file(a.rule);
    if (m.rules.empty()) throw Error(ErrorCode::Schema, "the Jerboa file has no rule", a.rule);
    return std::move(m.rules);
  }
  RuleInput in = load_rule_input(a.rule, a.rule_name);
  if (!in.is_scheme())
    throw Error(ErrorCode::Usage, "events are detected on rule schemes (pattern orbits); this is a concrete rule", a.rule);
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
      docs.push_back({{"rule", s.name}, {"error", (e.location().empty() ? "" : e.location() + ": ") + e.message()}});
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
  auto args = std::make_shared<EventsArgs>();
  CLI::App* sub = app.add_subcommand(
      "events", "Static topological events of a rule scheme per orbit type: creation, deletion, split, merge, modification, certain or to confirm");
  sub->add_option("rule", args->rule, "Rule scheme (gmr.rule JSON of kind scheme) or Jerboa .jme file (every rule)")->required();
  sub->add_option("--orbits", args->orbits, "Orbit types to analyse, e.g. \"<0,1>,<1,2>\" (default: all 2^(n+1))");
  sub->add_option("--rule", args->rule_name, "The rule of a .jme file (default: every rule)");
  sub->add_flag("--json", args->json, "Print JSON (format gmr.events, kind static)");
  set_action(sub, [args] { return run_events(*args); });
}

}  // namespace gmr::cli
