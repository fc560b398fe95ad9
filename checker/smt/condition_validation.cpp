#include "checker/smt/condition_validation.hpp"

#include <chrono>
#include <cstdio>
#include <set>
#include <sstream>
#include <tuple>

#include "checker/smt/counterexample.hpp"
#include "checker/smt/rule_space.hpp"
#include "model/core/error.hpp"
#include "model/io/rule_json.hpp"

namespace gmr::smt {

namespace {
double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
size_t nodes_of(const Rule& r) {
  return r.left().num_nodes() + r.added_nodes().size();
}
}  // namespace

ValidationReport validate_condition(const std::string& name, const ConditionEvaluator& evaluate,
                                    const ValidationOptions& opt) {
  if (opt.shards == 0 || opt.shard >= opt.shards)
    throw Error(ErrorCode::Usage, "shard " + std::to_string(opt.shard) + " of " + std::to_string(opt.shards), "--shard");
  const auto t0 = std::chrono::steady_clock::now();
  ValidationReport rep;
  rep.condition = name;
  rep.options = opt;
  std::vector<Rule> rules;
  std::vector<size_t> index;
  for_each_rule(opt.n, opt.kind, opt.max_nodes, opt.labels, [&](size_t k, const Rule& r) {
    if (k % opt.shards == opt.shard) {
      rules.push_back(r);
      index.push_back(k);
    }
    return true;
  });
  size_t next = 0;  // the family's size: random rules are indexed after it
  for (int m = 1; m <= opt.max_nodes; ++m) next += count_rules(m, opt.labels.size());
  std::mt19937_64 rng(opt.seed);
  for (size_t k = 0; k < opt.random; ++k) {
    const int nodes = opt.max_nodes + 1 + static_cast<int>(rng() % 2);
    Rule r = random_rule(rng, opt.n, opt.kind, nodes, opt.labels, "random" + std::to_string(k));
    if ((next + k) % opt.shards == opt.shard) {
      rules.push_back(std::move(r));
      index.push_back(next + k);
    }
  }
  rep.rules = rules.size();
  const auto tc = std::chrono::steady_clock::now();
  const std::vector<bool> holds = evaluate(rules);
  rep.condition_seconds = since(tc);
  EncodingOptions eo;
  eo.semantics = Semantics::Consistency;
  std::optional<SmtSession> session;
  std::optional<graph::MapFamily> family;
  if (opt.engine == Engine::Smt)
    session.emplace(MapSpec{opt.n, opt.kind}, opt.bound, static_cast<unsigned>(opt.max_nodes + (opt.random ? 2 : 0)), eo);
  else
    family.emplace(graph::map_family(opt.n, opt.kind, opt.bound));
  auto last_progress = std::chrono::steady_clock::now();
  rep.nodes_covered = opt.max_nodes;
  for (size_t k = 0; k < rules.size(); ++k) {
    if (opt.time_limit > 0 && since(t0) > opt.time_limit) {
      rep.time_limit_hit = true;
      rep.nodes_covered = std::min(opt.max_nodes, static_cast<int>(nodes_of(rules[k])) - 1);
      break;
    }
    const Rule& r = rules[k];
    const VerifyResult v = session ? session->verify(r) : verify_enum(r, *family, Semantics::Consistency);
    ++rep.checked;
    (holds[k] ? rep.holds : rep.fails)++;
    if (!v.applicable) {
      ++rep.vacuous;
    } else if (holds[k] && !v.preserves) {
      ++rep.unsound;
      const auto& cur = rep.smallest_unsound;
      if (!cur || nodes_of(r) < nodes_of(cur->rule) ||
          (nodes_of(r) == nodes_of(cur->rule) && v.counterexample->G.size() < cur->counterexample->G.size()))
        rep.smallest_unsound = ValidationWitness{r, index[k], v.counterexample};
    } else if (!holds[k] && v.preserves) {
      ++rep.incomplete;
      if (!rep.smallest_incomplete) rep.smallest_incomplete = ValidationWitness{r, index[k], std::nullopt};
    }
    if (opt.progress && std::chrono::duration<double>(std::chrono::steady_clock::now() - last_progress).count() > 0.5) {
      opt.progress(k + 1, rules.size());
      last_progress = std::chrono::steady_clock::now();
    }
  }
  if (opt.progress) opt.progress(rep.checked, rules.size());
  rep.seconds = since(t0);
  return rep;
}

std::string unsound_witness_text(const ValidationWitness& w) {
  std::ostringstream s;
  const auto& c = *w.counterexample;
  s << "\n    smallest: " << rule_text(w.rule) << "\n    on a map of " << c.G.size() << " darts, match";
  for (graph::Node v : w.rule.left().nodes())
    s << " " << w.rule.left().name(v) << "->" << c.match.node[v];
  if (c.gluing_fails)
    s << ": the gluing (dangling) condition fails";
  else
    s << ": H breaks " << c.violations.front().describe(c.H);
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
  const size_t darts = w.contains("counterexample") ? w["counterexample"]["G"]["darts"].get<size_t>() : 0;
  return {r.left().num_nodes() + r.added_nodes().size(), darts, w.at("index").get<size_t>()};
}
}  // namespace

nlohmann::ordered_json merge_reports(const std::vector<nlohmann::json>& shards) {
  if (shards.empty()) throw Error(ErrorCode::Usage, "no report to merge", "--merge");
  const char* same[] = {"format", "condition", "engine", "model", "n", "labels", "max_nodes", "random", "seed", "bound"};
  nlohmann::ordered_json out;
  std::set<unsigned> seen;
  unsigned m = 0;
  for (size_t k = 0; k < shards.size(); ++k) {
    const auto& j = shards[k];
    const std::string where = "report " + std::to_string(k + 1);
    if (!j.is_object() || j.value("format", "") != kValidationFormat)
      throw Error(ErrorCode::Usage, std::string("not a ") + kValidationFormat + " document", where);
    if (j.value("engine", "") == "symbolic")
      throw Error(ErrorCode::Usage, "a report of the symbolic engine covers the whole family: nothing to merge", where);
    for (const char* key : same)
      if (j.at(key) != shards[0].at(key)) throw Error(ErrorCode::Usage, std::string("differs in \"") + key + "\"", where);
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
  for (const char* key : {"rules", "checked", "holds", "fails", "vacuous", "unsound", "incomplete"}) {
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
  s << "condition " << r.condition << " on " << o.n << "-" << (o.kind == MapKind::OMap ? "O-map" : "G-map")
    << " rules of at most " << o.max_nodes << " nodes (arcs on labels";
  for (int i : o.labels) s << " " << i;
  s << "), maps of at most " << o.bound << " darts, engine " << to_string(o.engine);
  if (o.shards > 1) s << ", shard " << o.shard << "/" << o.shards;
  s << "\n  rules " << r.checked << " of " << r.rules << (r.time_limit_hit ? " (time limit hit)" : "")
    << "; covered: every rule of at most " << r.nodes_covered << " nodes\n";
 if (o.random) s << "  including " << o.random << " random rules of " << o.max_nodes + 1 << "-" << o.max_nodes + 2
                  << " nodes (seed " << o.seed << ")\n";
  s << "  condition holds on " << r.holds << ", fails on " << r.fails << "; vacuous (match no map) " << r.vacuous << "\n";
  s << "  sound: " << (r.sound() ? "yes" : "NO") << " (" << r.unsound << " unsound rules)";
  if (r.smallest_unsound) s << unsound_witness_text(*r.smallest_unsound);
  s << "\n  complete: " << (r.complete() ? "yes" : "NO") << " (" << r.incomplete << " incomplete rules)";
  if (r.smallest_incomplete)
    s << "\n    smallest: " << rule_text(r.smallest_incomplete->rule)
      << "\n    fails the condition, yet every match on every map of at most " << o.bound << " darts glues and preserves";
  char buf[96];
  std::snprintf(buf, sizeof buf, "\n  time %.3f s (condition %.3f s)\n", r.seconds, r.condition_seconds);
  s << buf;
  return s.str();
}

}  // namespace gmr::smt
