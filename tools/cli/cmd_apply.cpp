// `gmr apply RULE.json MAP.json [--match a=3,b=5] [-o OUT]`: one direct derivation (DPO) of a
// concrete rule on a map. The match is given by L-node=dart pairs: with an anchor in every
// connected component of L it is propagated along the arcs (linear); otherwise the first match
// (in enumeration order) that agrees with the given pairs and satisfies the gluing condition is
// used. Concrete rules do not carry embeddings (the output has none); rule schemes do, with their
// expressions (docs/embeddings.md).
// A rule the checker rejects is refused unless --force (rule_gate.hpp).
// Exit 0 when the result is a valid map (written to -o when given), 1 when the rule is refused, no
// match applies or the result breaks a constraint of the model (listed up to --limit), 2 on bad
// input.
// Rule schemes (gmr.rule kind "scheme", Jerboa .jme with --rule) go to scheme_apply.hpp
// (--hook D[,D...] or --all). --events [--orbits] writes the event log (checker/events/).
#include <cctype>
#include <iostream>
#include <memory>
#include <sstream>

#include "checker/events/concrete_scheme.hpp"
#include "checker/events/event_format.hpp"
#include "model/core/error.hpp"
#include "model/core/validity.hpp"
#include "model/map_io/json_writer.hpp"
#include "model/map_io/validity_report.hpp"
#include "model/rewrite/dpo.hpp"
#include "model/rule_io/rule_json.hpp"
#include "model/scheme/scheme_engine.hpp"
#include "tools/cli/cli.hpp"
#include "tools/cli/match_syntax.hpp"
#include "tools/cli/orbit_list.hpp"
#include "tools/cli/rule_gate.hpp"
#include "tools/cli/rule_input.hpp"
#include "tools/cli/scheme_apply.hpp"
#include "tools/cli/subcommand.hpp"
#include "tools/cli/summary.hpp"

namespace gmr::cli {
using namespace gmr::graph;
using namespace gmr::rewrite;

namespace {

struct ApplyArgs {
  std::string rule, input, from, output, to, match;
  bool json = false, force = false, lift = false;
  size_t limit = 20;
  std::string hooks, rule_name;  // rule schemes
  bool all = false;
  std::string events, orbits;
  bool no_embeddings = false;
};

// --events on a concrete rule: the rule is applied again as its scheme on <> (one dart per node,
// checker/events/concrete_scheme.hpp) at the same match, with the event log, which is written
// atomically. The result is the scheme engine's: the DPO's up to the indices of the created darts
// (the engine appends them, the DPO reuses the indices of deleted darts first), so that the log
// names the darts of the map written by -o. False (printed) when the engine refuses the rule.
bool log_concrete_application(const Rule& r, const Map& g, const std::vector<Dart>& md,
                              const std::vector<OrbitType>& types, const std::string& log_file,
                              MapDerivation& d) {
  const scheme::RuleScheme s = events::scheme_of_concrete_rule(r);
  const scheme::SchemeEngine engine(s);
  std::vector<Dart> hooks;
  for (const std::string& h : s.hooks) hooks.push_back(md[*s.left.find(h)]);
  const events::StaticEvents st = events::analyse(s, types);
  Map h = g;
  events::EventRecorder recorder(s, st);
  const scheme::SchemeApplication app = scheme::apply(engine, h, hooks, &recorder);
  if (!app) {
    std::cout << r.name() << " as a scheme on <>: " << app.why << "\n";
    return false;
  }
  write_output(log_file, io::dump_json(events::event_log_to_json(s, st, recorder.logs().back())));
  d.H = std::move(h);
  d.comatch = app.comatch;
  return true;
}

int run_apply(const ApplyArgs& a) {
  const RuleInput in = load_rule_input(a.rule, a.rule_name);
  if (auto refused = gate_rule(in, a.rule, a.force, !a.no_embeddings)) return *refused;
  if (in.is_scheme()) {
    if (!a.match.empty())
      throw Error(ErrorCode::Usage, "rule schemes are applied at hook darts (--hook), not --match",
                  "--match");
    return apply_scheme_input(
        *in.scheme, {a.rule, a.input, a.from, a.output, a.to, a.hooks, a.all, a.json, a.lift,
                     a.limit, a.no_embeddings, a.events, a.orbits});
  }
  if (!a.orbits.empty() && a.events.empty())
    throw Error(ErrorCode::Usage,
                "--orbits selects the orbit types of the event log: give it with --events",
                "--orbits");
  const std::vector<OrbitType> orbit_types = parse_orbit_list(a.orbits);
  if (!a.hooks.empty() || a.all)
    throw Error(ErrorCode::Usage,
                "--hook and --all apply rule schemes; give a concrete rule's match with --match",
                a.rule);
  const Rule& r = *in.concrete;
  const EmbeddedMap f = load_map(a.input, a.from);
  const Map& g = f.map;
  const auto pairs =
      a.match.empty() ? std::vector<std::pair<Node, Dart>>{} : parse_match_pairs(r, g, a.match);
  const DGraph dg = to_dgraph(g);
  const auto darts = g.darts();
  std::vector<Node> node_of(g.capacity(), kNoNode);  // to_dgraph numbers the live darts in order
  for (size_t k = 0; k < darts.size(); ++k) node_of[darts[k]] = Node(static_cast<uint32_t>(k));
  std::optional<Match> chosen;
  bool anchored = false;
  if (!pairs.empty()) {
    std::vector<std::pair<Node, Node>> anchors;
    for (auto [v, d] : pairs) anchors.emplace_back(v, node_of[d]);
    try {
      chosen = anchored_match(r.left(), dg, anchors);
      anchored = true;
      if (chosen && !satisfies_gluing(r, dg, *chosen)) {
        std::cout << "the match violates the gluing condition: "
                  << dangling_arcs(r, dg, *chosen)[0].describe(r, dg) << "\n";
        return kExitNegative;
      }
    } catch (const Error& e) {
      if (e.code() != ErrorCode::Usage)
        throw;  // not every component anchored, or L not combinatorial
    }
  }
  if (!anchored) {
    for_each_match(r.left(), dg, [&](const Match& m) {
      for (auto [v, d] : pairs)
        if (m.node[v] != node_of[d]) return true;
      if (!satisfies_gluing(r, dg, m)) return true;
      chosen = m;
      return false;
    });
  }
  if (!chosen) {
    std::cout << "no match of the left-hand side" << (pairs.empty() ? "" : " agreeing with --match")
              << " satisfies the gluing condition\n";
    return kExitNegative;
  }
  std::vector<Dart> md;
  for (Node v : chosen->node) md.push_back(darts[v.index()]);
  MapDerivation d;
  try {
    d = apply(r, g, md);
  } catch (const Error& e) {
    if (e.code() != ErrorCode::InvalidMap) throw;
    std::cout << "the result is not a map: " << e.location() << ": " << e.message() << "\n";
    return kExitNegative;
  }
  if (!a.events.empty() && !log_concrete_application(r, g, md, orbit_types, a.events, d))
    return kExitNegative;
  const ValidityReport rep = check_validity(d.H, a.limit);
  std::string match_text;
  for (Node v : r.left().nodes())
    match_text +=
        (v != Node(0) ? "," : "") + r.left().name(v) + "=" + std::to_string(md[v.index()]);
  if (a.json) {
    nlohmann::ordered_json j;
    j["rule"] = a.rule;
    j["map"] = a.input;
    j["match"] = match_text;
    j["valid"] = rep.ok();
    j["darts"] = d.H.size();
    j["change"] = change_to_json(summarize(g), summarize(d.H));
    nlohmann::ordered_json co = nlohmann::ordered_json::object();
    for (Node v : r.right().nodes()) co[r.right().name(v)] = d.comatch[v.index()];
    j["comatch"] = co;
    j["violations"] = io::violation_texts(rep);
    j["violations_not_listed"] = rep.truncated;
    print_json(j);
  } else {
    std::cout << "match " << match_text << ": " << d.H.size() << " darts, "
              << (rep.ok() ? "valid" : "INVALID") << "\n";
    if (const std::string c = describe_change(summarize(g), summarize(d.H)); !c.empty())
      std::cout << "  " << c << "\n";
    print_violations(rep);
  }
  if (!rep.ok()) return kExitNegative;
  if (!a.output.empty()) save_map(EmbeddedMap(d.H), a.output, output_format(a.output, a.to));
  return kExitOk;
}

}  // namespace

void register_apply(CLI::App& app) {
  auto [sub, args] =
      add_subcommand<ApplyArgs>(app, "apply",
                                "Apply a concrete rule once (DPO) at a match, or a rule scheme at "
                                "hook darts; exit 1 if it does not apply or breaks the map",
                                run_apply);
  sub->add_option("rule", args->rule,
                  "Rule file (gmr.rule JSON, concrete or scheme; Jerboa .jme with --rule)")
      ->required();
  add_map_input(sub, args->input, args->from, "map", "Map file (.json, .off, .obj)");
  sub->add_option("--match", args->match,
                  "L-node=dart pairs, e.g. a=3,b=5 (default: the first applicable match)");
  sub->add_option("-o,--output", args->output, "Write the result map here");
  sub->add_option("--to", args->to, std::string("Output format (") + kOutputFormats + ")");
  add_json_flag(sub, args->json, "Print JSON (schemes: with the match and comatch tables)");
  sub->add_option("--hook", args->hooks,
                  "Rule schemes: the hook dart(s), e.g. 5 or 5,17 (one per hook, in order)");
  sub->add_flag(
      "--all", args->all,
      "Rule schemes: apply at every dart where the scheme applies, a fresh hook each time");
  sub->add_option("--rule", args->rule_name, "The rule of a .jme file");
  sub->add_flag(
      "--no-embeddings", args->no_embeddings,
      "Rule schemes: drop the map's embeddings (positions, ...) and rewrite the topology only");
  sub->add_flag("--lift", args->lift,
                "Rule schemes of a higher dimension than the map: apply to the map lifted to it "
                "(new dimensions free)");
  sub->add_flag("--force", args->force,
                "Apply a rule the checker rejects (by default it is refused, exit 1)");
  sub->add_option("--limit", args->limit, "Maximum number of violations of the result listed")
      ->check(non_negative_integer())
      ->capture_default_str();
  sub->add_option("--events", args->events,
                  "Write the event log here (gmr.events JSON: every orbit type's events, named by "
                  "lowest dart, certain/confirmed/refuted; with --all one log per application; a "
                  "concrete rule is logged as its scheme on <>)");
  sub->add_option(
      "--orbits", args->orbits,
      "With --events: the orbit types logged, e.g. \"<0,1>,<1,2>\" (default: all 2^(n+1))");
}

}  // namespace gmr::cli
