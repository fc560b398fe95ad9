#include "tools/cli/scheme_apply.hpp"

#include <iostream>
#include <optional>
#include <sstream>

#include "checker/events/event_format.hpp"
#include "model/core/builders.hpp"
#include "model/core/embedded_map.hpp"
#include "model/core/error.hpp"
#include "model/core/validity.hpp"
#include "model/expr/compiled_scheme.hpp"
#include "model/expr/propagation.hpp"
#include "model/map_io/json_writer.hpp"
#include "model/map_io/validity_report.hpp"
#include "model/scheme/apply_everywhere.hpp"
#include "model/scheme/scheme_engine.hpp"
#include "tools/cli/cli.hpp"
#include "tools/cli/orbit_list.hpp"
#include "tools/cli/summary.hpp"

namespace gmr::cli {
using namespace gmr::scheme;

namespace {

std::vector<Dart> parse_hooks(const std::string& text, const Map& g) {
  std::vector<Dart> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    size_t used = 0;
    unsigned long d = 0;
    try {
      d = std::stoul(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != item.size() || item.empty() || d > UINT32_MAX || !g.alive(static_cast<Dart>(d)))
      throw Error(ErrorCode::Usage, "\"" + item + "\" is not a dart of the map", "--hook");
    out.push_back(static_cast<Dart>(d));
  }
  if (out.empty()) throw Error(ErrorCode::Usage, "no dart given", "--hook");
  return out;
}

nlohmann::ordered_json table(const GraphScheme& side, const std::vector<Dart>& t, size_t s) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (uint32_t v = 0; v < side.size(); ++v) {
    nlohmann::ordered_json row = nlohmann::ordered_json::array();
    for (size_t b = 0; b < s; ++b) row.push_back(t[v * s + b]);
    j[side.nodes[v].name] = row;
  }
  return j;
}

// The applications made and the hook darts of each (empty for a scheme without hook).
struct Applied {
  std::vector<SchemeApplication> apps;
  std::vector<std::vector<Dart>> hooks_used;
};

// Usage errors of --hook / --all, before the map is read.
void check_hook_arguments(const RuleScheme& s, const SchemeApplyArgs& a) {
  const size_t nhooks = s.hooks.size();
  if (a.all && !a.hooks.empty())
    throw Error(ErrorCode::Usage, "give either --hook or --all", "--all");
  if (a.all && nhooks != 1)
    throw Error(ErrorCode::Usage,
                "--all applies schemes with one hook; \"" + s.name + "\" has " +
                    std::to_string(nhooks) + " (give them with --hook)",
                "--all");
  if (!a.orbits.empty() && a.events.empty())
    throw Error(ErrorCode::Usage,
                "--orbits selects the orbit types of the event log: give it with --events",
                "--orbits");
  if (!a.all && a.hooks.empty() && nhooks > 0)
    throw Error(ErrorCode::Usage,
                "the scheme has " + std::to_string(nhooks) +
                    " hook(s): give the dart(s) with --hook D[,D...] or use --all",
                "--hook");
}

// Prints why the scheme was not applied. `applications` is printed with --all only.
void print_not_applicable(const RuleScheme& s, const SchemeApplyArgs& a, NotApplicableReason reason,
                          const std::string& why, const std::string& text) {
  if (a.json) {
    nlohmann::ordered_json j;
    j["rule"] = s.name;
    j["map"] = a.input;
    j["applied"] = false;
    if (a.all) j["applications"] = 0;
    j["reason"] = to_string(reason);
    j["why"] = why;
    print_json(j);
  } else {
    std::cout << text << "\n";
  }
}

// --hook D[,D...] (or no hook): one application; nullopt when not applicable (already printed).
std::optional<Applied> apply_at_hooks(const SchemeEngine& engine, Map& g, const SchemeApplyArgs& a,
                                      ApplicationObserver* obs) {
  const RuleScheme& s = engine.scheme();
  const std::vector<Dart> hooks = a.hooks.empty() ? std::vector<Dart>{} : parse_hooks(a.hooks, g);
  SchemeApplication app;
  if (a.events.empty()) {
    app = scheme::apply(engine, g, hooks, obs);  // wrong count, dead dart: Error (exit 2)
  } else {
    const events::StaticEvents st = events::analyse(s, parse_orbit_list(a.orbits));
    events::EventRecorder recorder(s, st, obs);
    app = scheme::apply(engine, g, hooks, &recorder);
    if (app)
      write_output(a.events,
                   io::dump_json(events::event_log_to_json(s, st, recorder.logs().back())));
  }
  if (!app) {
    print_not_applicable(s, a, app.reason, app.why, s.name + ": " + app.why);
    return std::nullopt;
  }
  Applied out;
  out.hooks_used.push_back(hooks);
  out.apps.push_back(std::move(app));
  return out;
}

// --all: apply_everywhere; nullopt when applicable at no dart (already printed).
std::optional<Applied> apply_at_every_dart(const SchemeEngine& engine, Map& g,
                                           const SchemeApplyArgs& a, ApplicationObserver* obs) {
  const RuleScheme& s = engine.scheme();
  const std::vector<Dart> darts = g.darts();
  // With --events, every application is logged on the map as it is just before and after it.
  std::optional<events::StaticEvents> st;
  std::optional<events::EventRecorder> recorder;
  if (!a.events.empty()) {
    st = events::analyse(s, parse_orbit_list(a.orbits));
    recorder.emplace(s, *st, obs);
  }
  // Tables only with --json.
  EverywhereApplication all =
      apply_everywhere(engine, g, {.keep_tables = a.json, .observer = recorder ? &*recorder : obs});
  if (recorder && !all.applications.empty())
    write_output(a.events, io::dump_json(events::event_logs_to_json(s, *st, recorder->logs())));
  if (all.applications.empty()) {
    const SchemeApplication& last = all.last_failure;
    const std::string why = darts.empty()
                                ? "the map has no dart"
                                : last.why + " (at dart " + std::to_string(darts.front()) +
                                      ", and at every other dart)";
    print_not_applicable(s, a, last.reason, why, s.name + ": not applicable at any dart; " + why);
    return std::nullopt;
  }
  Applied out;
  out.apps = std::move(all.applications);
  for (Dart d : all.hooks) out.hooks_used.push_back({d});
  return out;
}

// The map before and after, for the report of what changed.
struct Change {
  size_t darts_before;
  MapSummary before, after;
};

// A surface given to a volume scheme: lifted with --lift (builders.hpp), else a usage error
// that says so.
void lift_to_scheme(const RuleScheme& s, const SchemeApplyArgs& a, Map& g) {
  if (g.dimension() >= s.dimension || g.is_omap()) return;
  if (!a.lift)
    throw Error(ErrorCode::Usage,
                "the scheme rewrites " + std::to_string(s.dimension) + "-G-maps, the map is a " +
                    map_name(g) + ": --lift applies it to the map lifted to dimension " +
                    std::to_string(s.dimension) + " (new dimensions free)",
                a.input);
  g = lift(g, s.dimension);
}

// Prints the applications, the dart counts, the change in cells and the validity of the result.
void print_applied(const RuleScheme& s, const SchemeApplyArgs& a, const Applied& r,
                   const Change& change, const Map& g, const ValidityReport& rep,
                   const expr::EmbeddingPropagation& prop, const EmbeddedMap& m) {
  const size_t before = change.darts_before;
  const auto& apps = r.apps;
  const auto& hooks_used = r.hooks_used;
  size_t added = 0, deleted = 0;
  for (const auto& app : apps) {
    added += app.darts_added;
    deleted += app.darts_deleted;
  }
  if (a.json) {
    nlohmann::ordered_json j;
    j["rule"] = s.name;
    j["map"] = a.input;
    j["applied"] = true;
    j["applications"] = apps.size();
    j["darts_before"] = before;
    j["darts"] = g.size();
    j["darts_added"] = added;
    j["darts_deleted"] = deleted;
    j["valid"] = rep.ok();
    j["change"] = change_to_json(change.before, change.after);
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (size_t k = 0; k < apps.size(); ++k) {
      nlohmann::ordered_json e;
      e["hooks"] = hooks_used[k];
      e["orbit"] = apps[k].orbit;
      e["match"] = table(s.left, apps[k].match, apps[k].orbit_size());
      e["comatch"] = table(s.right, apps[k].comatch, apps[k].orbit_size());
      list.push_back(e);
    }
    j["tables"] = list;
    j["violations"] = io::violation_texts(rep);
    j["violations_not_listed"] = rep.truncated;
    nlohmann::ordered_json em = nlohmann::ordered_json::array();
    for (const auto& f : m.fields) em.push_back(f.name());
    j["embeddings"] = em;
    j["evaluations"] = prop.evaluations();
    nlohmann::ordered_json is = nlohmann::ordered_json::array();
    for (const auto& i : prop.issues())
      is.push_back(
          {{"code", i.code}, {"embedding", i.embedding}, {"dart", i.dart}, {"message", i.message}});
    j["embedding_issues"] = is;
    print_json(j);
  } else {
    std::cout << s.name << ": applied " << apps.size() << " time" << (apps.size() == 1 ? "" : "s");
    if (apps.size() == 1 && !hooks_used[0].empty()) {
      std::cout << " at hook" << (hooks_used[0].size() > 1 ? "s " : " ");
      for (size_t k = 0; k < hooks_used[0].size(); ++k)
        std::cout << (k ? "," : "") << hooks_used[0][k];
    }
    std::cout << ": " << before << " -> " << g.size() << " darts (+" << added << " -" << deleted
              << "), " << (rep.ok() ? "valid" : "INVALID") << "\n";
    if (const std::string c = describe_change(change.before, change.after); !c.empty())
      std::cout << "  " << c << "\n";
    print_violations(rep);
    if (!m.fields.empty()) {
      std::cout << "embeddings: ";
      for (size_t k = 0; k < m.fields.size(); ++k)
        std::cout << (k ? ", " : "") << m.fields[k].name() << " " << m.fields[k].orbit().str();
      std::cout << " (" << prop.evaluations() << " expression evaluations)\n";
    }
    if (prop.issue_count() > 0)
      std::cout << "embedding issues: " << prop.issue_count()
                << " (the result is not embedding-consistent)\n";
    for (const auto& i : prop.issues())
      std::cout << "  " << i.code << ": embedding " << i.embedding << ", dart " << i.dart << ": "
                << i.message << "\n";
  }
}

// The engine of `s`; a structural problem of the scheme is located in the rule file.
SchemeEngine engine_for(const RuleScheme& s, const SchemeApplyArgs& a) {
  try {
    return SchemeEngine(s);
  } catch (const Error& e) {
    throw Error(e.code(), e.message() + " (gmr check lists every problem of the rule)",
                a.rule + ": rule " + s.name + (e.location().empty() ? "" : ": " + e.location()));
  }
}

}  // namespace

int apply_scheme_input(const RuleScheme& s, const SchemeApplyArgs& a) {
  const SchemeEngine engine = engine_for(s, a);
  check_hook_arguments(s, a);
  const expr::CompiledScheme cs = expr::compile_scheme(s);
  EmbeddedMap m = load_map(a.input, a.from);
  if (a.no_embeddings) m.fields.clear();
  Map& g = m.map;
  lift_to_scheme(s, a, g);
  expr::EmbeddingPropagation prop(cs, m);
  const size_t before = g.size();
  const MapSummary summary_before = summarize(g);
  const std::optional<Applied> r =
      a.all ? apply_at_every_dart(engine, g, a, &prop) : apply_at_hooks(engine, g, a, &prop);
  if (!r) return kExitNegative;
  const ValidityReport rep = check_validity(g, a.limit);
  print_applied(s, a, *r, {before, summary_before, summarize(g)}, g, rep, prop, m);
  if (!rep.ok() || prop.issue_count() > 0) return kExitNegative;
  if (!a.output.empty()) save_map(m, a.output, output_format(a.output, a.to));
  return kExitOk;
}

}  // namespace gmr::cli
