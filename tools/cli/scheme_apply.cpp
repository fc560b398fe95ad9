#include "tools/cli/scheme_apply.hpp"

#include <iostream>
#include <sstream>

#include "model/core/error.hpp"
#include "model/scheme/scheme_engine.hpp"
#include "model/core/validity.hpp"
#include "tools/cli/cli.hpp"

namespace gmr::cli {
using namespace gmr::scheme;

namespace {

std::vector<Dart> parse_hooks(const std::string& text, const GMap& g) {
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

}  // namespace

int apply_scheme_input(const RuleScheme& s, const SchemeApplyArgs& a) {
  const SchemeEngine engine(s);
  const size_t nhooks = s.hooks.size();
  if (a.all && !a.hooks.empty()) throw Error(ErrorCode::Usage, "give either --hook or --all", "--all");
  if (a.all && nhooks != 1)
    throw Error(ErrorCode::Usage,
                "--all applies schemes with one hook; \"" + s.name + "\" has " + std::to_string(nhooks) +
                    " (give them with --hook)",
                "--all");
  if (!a.all && a.hooks.empty() && nhooks > 0)
    throw Error(ErrorCode::Usage,
                "the scheme has " + std::to_string(nhooks) + " hook(s): give the dart(s) with --hook D[,D...] or use --all",
                "--hook");
  GMapFile f = load_map(a.input, a.from);
  GMap& g = f.map;
  const size_t before = g.size();
  std::vector<SchemeApplication> apps;
  std::vector<std::vector<Dart>> hooks_used;
  if (!a.all) {
    const std::vector<Dart> hooks = a.hooks.empty() ? std::vector<Dart>{} : parse_hooks(a.hooks, g);
    SchemeApplication app = engine.apply(g, hooks);  // wrong count, dead dart: Error (exit 2)
    if (!app) {
      if (a.json) {
        nlohmann::ordered_json j;
        j["rule"] = s.name;
        j["map"] = a.input;
        j["applied"] = false;
        j["reason"] = to_string(app.reason);
        j["why"] = app.why;
        print_json(j);
      } else {
        std::cout << s.name << ": " << app.why << "\n";
      }
      return kExitNegative;
    }
    hooks_used.push_back(hooks);
    apps.push_back(std::move(app));
  } else {
    const std::vector<Dart> darts = g.darts();
    std::vector<bool> used(g.capacity(), false);
    SchemeApplication last;
    for (Dart d : darts) {
      if (used[d] || !g.alive(d)) continue;
      SchemeApplication app = engine.apply(g, {d});
      if (!app) {
        if (apps.empty()) last = std::move(app);
        continue;
      }
      for (Dart x : app.match)
        if (x < used.size()) used[x] = true;
      hooks_used.push_back({d});
      if (!a.json) {  // the tables are printed only with --json
        app.orbit.clear();
        app.match.clear();
        app.comatch.clear();
      }
      apps.push_back(std::move(app));
    }
    if (apps.empty()) {
      const std::string why = darts.empty() ? "the map has no dart" : last.why + " (at dart " + std::to_string(darts.front()) + ", and at every other dart)";
      if (a.json) {
        nlohmann::ordered_json j;
        j["rule"] = s.name;
        j["map"] = a.input;
        j["applied"] = false;
        j["applications"] = 0;
        j["reason"] = to_string(last.reason);
        j["why"] = why;
        print_json(j);
      } else {
        std::cout << s.name << ": not applicable at any dart; " << why << "\n";
      }
      return kExitNegative;
    }
  }
  const ValidityReport rep = check_validity(g);
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
    nlohmann::ordered_json vs = nlohmann::ordered_json::array();
    for (const auto& v : rep.violations) vs.push_back(v.describe());
    j["violations"] = vs;
    print_json(j);
  } else {
    std::cout << s.name << ": applied " << apps.size() << " time" << (apps.size() == 1 ? "" : "s");
    if (apps.size() == 1 && !hooks_used[0].empty()) {
      std::cout << " at hook" << (hooks_used[0].size() > 1 ? "s " : " ");
      for (size_t k = 0; k < hooks_used[0].size(); ++k) std::cout << (k ? "," : "") << hooks_used[0][k];
    }
    std::cout << ": " << before << " -> " << g.size() << " darts (+" << added << " -" << deleted << "), "
              << (rep.ok() ? "valid" : "INVALID") << "\n";
    for (const auto& v : rep.violations) std::cout << "  " << v.describe() << "\n";
  }
  if (!rep.ok()) return kExitNegative;
  if (!a.output.empty()) save_map(GMapFile{g, {}}, a.output, output_format(a.output, a.to));
  return kExitOk;
}

}  // namespace gmr::cli
