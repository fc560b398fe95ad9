#include "checker/smt/validation_format.hpp"

#include <cstdio>
#include <set>
#include <sstream>
#include <tuple>

#include "checker/smt/counterexample.hpp"
#include "checker/smt/rule_space.hpp"
#include "model/core/error.hpp"
#include "model/rule_io/rule_json.hpp"

namespace gmr::smt {

namespace {

// "condition NAME on n-G-map rules of at most N nodes (arcs on labels 0 1), maps of at most B
// darts, engine ", the engine's name to follow.
std::string family_text(const std::string& condition, const ValidationOptions& o) {
  std::ostringstream s;
  s << "condition " << condition << " on " << o.n << "-"
    << (o.kind == MapKind::OMap ? "O-map" : "G-map") << " rules of at most " << o.max_nodes
    << " nodes (arcs on labels";
  for (int i : o.labels) s << " " << i;
  s << "), maps of at most " << o.bound << " darts, engine ";
  return s.str();
}

// The text lines of an incompleteness witness: the rule, which fails the condition and yet
// preserves the model on every map of at most `bound` darts.
std::string incomplete_witness_text(const ValidationWitness& w, unsigned bound) {
  return "\n    smallest: " + rule_text(w.rule) +
         "\n    fails the condition, yet every match on every map of at most " +
         std::to_string(bound) + " darts glues and preserves";
}

}  // namespace

std::string unsound_witness_text(const ValidationWitness& w) {
  std::ostringstream s;
  const auto& c = *w.counterexample;
  s << "\n    smallest: " << rule_text(w.rule) << "\n    on a map of " << c.G.size()
    << " darts, match";
  for (graph::Node v : w.rule.left().nodes())
    s << " " << w.rule.left().name(v) << "->" << c.match.node[v];
  if (c.gluing_fails)
    s << ": the gluing (dangling) condition fails";
  else
    s << ": H breaks " << graph::to_text(c.violations.front(), c.H);
  return s.str();
}

nlohmann::ordered_json validation_header(const std::string& condition, const std::string& engine,
                                         const ValidationOptions& o) {
  nlohmann::ordered_json j;
  j["format"] = kValidationFormat;
  j["version"] = 1;
  j["condition"] = condition;
  if (!engine.empty()) j["engine"] = engine;
  j["model"] = o.kind == MapKind::OMap ? "omap" : "gmap";
  j["n"] = o.n;
  j["labels"] = o.labels;
  return j;
}

nlohmann::ordered_json to_json(const ValidationReport& r) {
  const ValidationOptions& o = r.options;
  nlohmann::ordered_json j = validation_header(r.condition, to_string(o.engine), o);
  j["max_nodes"] = o.max_nodes;
  j["random"] = o.random;
  j["seed"] = o.seed;
  j["bound"] = o.bound;
  j["shard"] = std::to_string(o.shard) + "/" + std::to_string(o.shards);
  j["rules"] = r.rules;
  j["checked"] = r.checked;
  j["nodes_covered"] = r.nodes_covered;
  j["time_limit_hit"] = r.time_limit_hit;
  put_verdict_counts(j, r);
  if (r.smallest_unsound) {
    const auto& w = *r.smallest_unsound;
    nlohmann::ordered_json e;
    e["index"] = w.index;
    e["rule"] = io::rule_to_json(w.rule);
    e["counterexample"] = to_json(w.rule, o.bound, *w.counterexample);
    j["smallest_unsound"] = e;
  }
  if (r.smallest_incomplete) {
    const auto& w = *r.smallest_incomplete;
    nlohmann::ordered_json e;
    e["index"] = w.index;
    e["rule"] = io::rule_to_json(w.rule);
    j["smallest_incomplete"] = e;
  }
  j["seconds"] = r.seconds;
  j["condition_seconds"] = r.condition_seconds;
  return j;
}

namespace {
// (nodes, darts, index) of a witness in a report, for the "smallest" order.
std::tuple<size_t, size_t, size_t> witness_key(const nlohmann::json& w) {
  const Rule r = io::rule_from_json(w.at("rule"));
  const size_t darts =
      w.contains("counterexample") ? w["counterexample"]["G"]["darts"].get<size_t>() : 0;
  return {r.left().num_nodes() + r.added_nodes().size(), darts, w.at("index").get<size_t>()};
}
}  // namespace

nlohmann::ordered_json merge_reports(const std::vector<nlohmann::json>& shards) {
  if (shards.empty()) throw Error(ErrorCode::Usage, "no report to merge", "--merge");
  const char* same[] = {"format", "condition", "engine", "model", "n",
                        "labels", "max_nodes", "random", "seed",  "bound"};
  nlohmann::ordered_json out;
  std::set<unsigned> seen;
  unsigned m = 0;
  for (size_t k = 0; k < shards.size(); ++k) {
    const auto& j = shards[k];
    const std::string where = "report " + std::to_string(k + 1);
    if (!j.is_object() || j.value("format", "") != kValidationFormat)
      throw Error(ErrorCode::Usage, std::string("not a ") + kValidationFormat + " document", where);
    if (j.value("engine", "") == "symbolic")
      throw Error(ErrorCode::Usage,
                  "a report of the symbolic engine covers the whole family: nothing to merge",
                  where);
    for (const char* key : same)
      if (j.at(key) != shards[0].at(key))
        throw Error(ErrorCode::Usage, std::string("differs in \"") + key + "\"", where);
    const std::string shard = j.at("shard").get<std::string>();
    unsigned a = 0, b = 0;
    if (std::sscanf(shard.c_str(), "%u/%u", &a, &b) != 2 || (m && b != m) || !seen.insert(a).second)
      throw Error(ErrorCode::Usage, "shard " + shard + " repeated or of another sweep", where);
    m = b;
  }
  for (const char* key : same) out[key] = shards[0].at(key);
  out["version"] = 1;
  std::string list;
  for (unsigned a : seen) list += (list.empty() ? "" : ",") + std::to_string(a);
  out["shard"] = list + "/" + std::to_string(m);
  for (const char* key :
       {"rules", "checked", "holds", "fails", "vacuous", "unsound", "incomplete"}) {
    size_t sum = 0;
    for (const auto& j : shards) sum += j.at(key).get<size_t>();
    out[key] = sum;
  }
  int covered = INT32_MAX;
  bool hit = false;
  double seconds = 0;
  for (const auto& j : shards) {
    covered = std::min(covered, j.at("nodes_covered").get<int>());
    hit = hit || j.at("time_limit_hit").get<bool>();
    seconds += j.at("seconds").get<double>();
  }
  out["nodes_covered"] = covered;
  out["time_limit_hit"] = hit;
  out["sound"] = out["unsound"] == 0;
  out["complete"] = out["incomplete"] == 0;
  for (const char* key : {"smallest_unsound", "smallest_incomplete"}) {
    const nlohmann::json* best = nullptr;
    for (const auto& j : shards)
      if (j.contains(key) && (!best || witness_key(j[key]) < witness_key(*best))) best = &j[key];
    if (best) out[key] = *best;
  }
  out["seconds"] = seconds;  // summed over the shards
  return out;
}

std::string to_text(const ValidationReport& r) {
  const ValidationOptions& o = r.options;
  std::ostringstream s;
  s << family_text(r.condition, o) << to_string(o.engine);
  if (o.shards > 1) s << ", shard " << o.shard << "/" << o.shards;
  s << "\n  rules " << r.checked << " of " << r.rules
    << (r.time_limit_hit ? " (time limit hit)" : "") << "; covered: every rule of at most "
    << r.nodes_covered << " nodes\n";
  if (o.random)
    s << "  including " << o.random << " random rules of " << o.max_nodes + 1 << "-"
      << o.max_nodes + 2 << " nodes (seed " << o.seed << ")\n";
  s << "  condition holds on " << r.holds << ", fails on " << r.fails << "; vacuous (match no map) "
    << r.vacuous << "\n";
  s << "  sound: " << (r.sound() ? "yes" : "NO") << " (" << r.unsound << " unsound rules)";
  if (r.smallest_unsound) s << unsound_witness_text(*r.smallest_unsound);
  s << "\n  complete: " << (r.complete() ? "yes" : "NO") << " (" << r.incomplete
    << " incomplete rules)";
  if (r.smallest_incomplete) s << incomplete_witness_text(*r.smallest_incomplete, o.bound);
  char buf[96];
  std::snprintf(buf, sizeof buf, "\n  time %.3f s (condition %.3f s)\n", r.seconds,
                r.condition_seconds);
  s << buf;
  return s.str();
}

nlohmann::ordered_json to_json(const SymbolicReport& r) {
  const ValidationOptions& o = r.options;
  nlohmann::ordered_json j = validation_header(r.condition, "symbolic", o);
  j["max_nodes"] = o.max_nodes;
  j["bound"] = o.bound;
  j["rules"] = r.rules;
  j["time_limit_hit"] = !(r.sound_decided && r.complete_decided);
  j["sound"] =
      r.sound_decided ? nlohmann::ordered_json(r.sound()) : nlohmann::ordered_json(nullptr);
  j["complete"] =
      r.complete_decided ? nlohmann::ordered_json(r.complete()) : nlohmann::ordered_json(nullptr);
  if (r.smallest_unsound) {
    const auto& w = *r.smallest_unsound;
    nlohmann::ordered_json e;
    e["rule"] = io::rule_to_json(w.rule);
    e["counterexample"] = to_json(w.rule, o.bound, *w.counterexample);
    j["smallest_unsound"] = e;
  }
  if (r.smallest_incomplete)
    j["smallest_incomplete"] = {{"rule", io::rule_to_json(r.smallest_incomplete->rule)}};
  j["refinements"] = r.refinements;
  j["cycle_lemmas"] = r.cycle_lemmas;
  j["cycle_patterns"] = r.cycle_patterns;
  j["cycle_cubes"] = r.cycle_cubes;
  j["cycle_table_seconds"] = r.cycle_table_seconds;
  j["sound_seconds"] = r.sound_seconds;
  j["complete_seconds"] = r.complete_seconds;
  j["seconds"] = r.cycle_table_seconds + r.sound_seconds + r.complete_seconds;
  return j;
}

std::string to_text(const SymbolicReport& r) {
  const ValidationOptions& o = r.options;
  std::ostringstream s;
  s << family_text(r.condition, o) << "symbolic\n  every rule of the family at once (" << r.rules
    << " rules)\n";
  char buf[200];
  s << "  sound: ";
  if (!r.sound_decided) {
    s << "undecided (time limit hit)";
  } else {
    s << (r.sound() ? "yes" : "NO");
    std::snprintf(buf, sizeof buf, " (%.3f s)", r.sound_seconds);
    s << buf;
  }
  if (r.smallest_unsound) s << unsound_witness_text(*r.smallest_unsound);
  s << "\n  complete: ";
  if (!r.complete_decided) {
    s << "undecided (time limit hit)";
  } else {
    s << (r.complete() ? "yes" : "NO");
  }
  std::snprintf(buf, sizeof buf, " (%.3f s, %zu refinements)", r.complete_seconds, r.refinements);
  s << buf;
  if (!MapSpec{o.n, o.kind}.cycle_pairs().empty()) {
    std::snprintf(buf, sizeof buf,
                  "\n  cycle condition: %zu component patterns tabulated by the concrete checker "
                  "(%zu cubes, %.3f s), %zu lemmas from it",
                  r.cycle_patterns, r.cycle_cubes, r.cycle_table_seconds, r.cycle_lemmas);
  } else {
    buf[0] = 0;
  }
  s << buf;
  if (r.smallest_incomplete) s << incomplete_witness_text(*r.smallest_incomplete, o.bound);
  std::snprintf(buf, sizeof buf, "\n  time %.3f s\n",
                r.cycle_table_seconds + r.sound_seconds + r.complete_seconds);
  s << buf;
  return s.str();
}

std::string to_text(const SchemeValidationReport& r) {
  std::ostringstream s;
  s << "scheme condition " << r.condition << " on " << r.schemes << " schemes, G-maps of at most "
    << r.bound << " darts (every hook orbit of at most " << r.bound << " darts)\n  holds on "
    << r.holds << ", fails on " << r.fails << "; vacuous " << r.vacuous
    << "\n  sound: " << (r.sound() ? "yes" : "NO") << " (" << r.unsound << " unsound)";
  if (r.smallest_unsound) {
    const auto& w = *r.smallest_unsound;
    const auto& c = *w.result.result->counterexample;
    s << "\n    smallest: " << w.scheme.name << " on a hook orbit of "
      << w.result.orbit->darts.size() << " darts, a map of " << c.G.size() << " darts: "
      << (c.gluing_fails ? std::string("the gluing (dangling) condition fails")
                         : graph::to_text(c.violations.front(), c.H));
  }
  s << "\n  complete: " << (r.complete() ? "yes" : "NO") << " (" << r.incomplete << " incomplete)";
  if (r.first_incomplete) s << "\n    first: " << r.first_incomplete->name;
  char buf[64];
  std::snprintf(buf, sizeof buf, "\n  time %.3f s\n", r.seconds);
  s << buf;
  return s.str();
}

nlohmann::ordered_json to_json(const SchemeValidationReport& r, bool sufficient_only) {
  nlohmann::ordered_json j;
  j["format"] = "gmr.scheme-condition-validation";
  j["version"] = 1;
  j["condition"] = r.condition;
  j["bound"] = r.bound;
  j["schemes"] = r.schemes;
  put_verdict_counts(j, r);
  j["sufficient_only"] = sufficient_only;
  if (r.smallest_unsound) {
    const auto& w = *r.smallest_unsound;
    nlohmann::ordered_json e;
    e["scheme"] = w.scheme.name;
    e["counterexample"] = to_json(*w.result.instance, r.bound, *w.result.result->counterexample);
    j["smallest_unsound"] = e;
  }
  if (r.first_incomplete) j["first_incomplete"] = r.first_incomplete->name;
  j["seconds"] = r.seconds;
  return j;
}

}  // namespace gmr::smt
