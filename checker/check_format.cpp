#include "checker/check_format.hpp"

namespace gmr::checker {

static std::string join(const std::vector<std::string>& v, const char* sep) {
  std::string s;
  for (size_t k = 0; k < v.size(); ++k) s += (k ? sep : "") + v[k];
  return s;
}

std::string to_text(const Diagnostic& d) {
  std::string s = std::string(to_string(d.severity)) + " [" + d.code + "] " +
                  condition_text(d.condition, d.i, d.j) + ": " + d.message;
  if (!d.nodes.empty()) s += "; nodes: " + join(d.nodes, ", ");
  if (!d.arcs.empty()) s += "; arcs: " + join(d.arcs, ", ");
  if (!d.path.empty())
    s += "; path" + (d.side ? std::string(" in ") + to_string(*d.side) : "") + ": " +
         join(d.path, " ");
  return s;
}

// One line of a scheme report: "error C-word [C(0,2)] L a,b arc a -1- b: message".
static std::string scheme_line(const Diagnostic& d) {
  std::string s = std::string(to_string(d.severity)) + " " + d.code + " [" +
                  condition_text(d.condition, d.i, d.j) + "]";
  if (d.side) s += std::string(" ") + to_string(*d.side);
  if (!d.nodes.empty()) s += " " + join(d.nodes, ",");
  for (const auto& a : d.arcs) s += " arc " + a;
  return s + ": " + d.message;
}

static std::string rule_text(const CheckReport& r) {
  std::string s = "rule" + (r.rule.empty() ? std::string() : " " + r.rule) + " (" +
                  to_string(r.kind) + ", n=" + std::to_string(r.n) +
                  "): " + (r.ok() ? "all conditions hold" : "some conditions fail") + "\n";
  s += "conditions:";
  for (const auto& [c, h] : r.conditions) s += " " + c + (h ? "=ok" : "=FAIL");
  s += "\n";
  for (const auto& d : r.diagnostics) s += to_text(d) + "\n";
  return s;
}

static std::string scheme_text(const CheckReport& r) {
  std::string s = "rule " + (r.rule.empty() ? std::string("(unnamed)") : r.rule) + ": " +
                  (r.ok() ? "accepted" : "rejected") + " (" + std::to_string(r.errors()) +
                  " error(s), " + std::to_string(r.warnings()) + " warning(s))\n";
  s += "  conditions:";
  for (const auto& [c, ok] : r.conditions) s += " " + c + (ok ? "=ok" : "=FAIL");
  s += "\n";
  for (const auto& d : r.diagnostics) s += "  " + scheme_line(d) + "\n";
  return s;
}

std::string to_text(const CheckReport& r) {
  return r.subject == CheckSubject::Rule ? rule_text(r) : scheme_text(r);
}

nlohmann::ordered_json to_json(const Diagnostic& d) {
  nlohmann::ordered_json j;
  j["code"] = d.code;
  j["severity"] = to_string(d.severity);
  j["condition"] = d.condition;
  if (d.i >= 0) {
    j["dims"] = nlohmann::ordered_json::array({d.i});
    if (d.j >= 0) j["dims"].push_back(d.j);
  }
  j["message"] = d.message;
  if (!d.nodes.empty()) j["nodes"] = d.nodes;
  if (!d.arcs.empty()) j["arcs"] = d.arcs;
  if (!d.path.empty()) j["path"] = d.path;
  if (d.side) j["side"] = to_string(*d.side);
  return j;
}

nlohmann::ordered_json check_document(const char* subject, bool ok) {
  nlohmann::ordered_json j;
  j["format"] = "gmr.check";
  j["version"] = 1;
  j["subject"] = subject;
  j["ok"] = ok;
  return j;
}

nlohmann::ordered_json to_json(const CheckReport& r) {
  const bool scheme = r.subject == CheckSubject::Scheme;
  nlohmann::ordered_json j = check_document(scheme ? "scheme" : "rule", r.ok());
  if (scheme) {
    j["rule"] = r.rule;
    j["verdict"] = r.ok() ? "accepted" : "rejected";
    j["errors"] = r.errors();
    j["warnings"] = r.warnings();
  } else {
    if (!r.rule.empty()) j["rule"] = r.rule;
    j["map"] = r.kind == MapKind::OMap ? "omap" : "gmap";
    j["n"] = r.n;
  }
  j["conditions"] = nlohmann::ordered_json::object();
  for (const auto& [c, h] : r.conditions) j["conditions"][c] = h;
  j["diagnostics"] = nlohmann::ordered_json::array();
  for (const auto& d : r.diagnostics) j["diagnostics"].push_back(to_json(d));
  return j;
}

std::string to_text(const SemanticWitness& w, const Rule& r, const MapFamily& f) {
  const Map& g = f.maps[w.map_index];
  std::string s =
      "map #" + std::to_string(w.map_index) + " (" + std::to_string(g.size()) + " darts;";
  for (int i = g.lowest_dim(); i <= g.dimension(); ++i) {
    s += std::string(" ") + (g.is_omap() ? "beta" : "alpha") + std::to_string(i) + "=[";
    for (Dart d = 0; d < g.capacity(); ++d) s += (d ? "," : "") + std::to_string(g.alpha(i, d));
    s += "]";
  }
  s += "), match";
  for (graph::Node v : r.left().nodes())
    s += " " + r.left().name(v) + "->" + std::to_string(graph::dart_of(w.match.node[v]));
  s += "; H breaks:";
  for (size_t k = 0; k < w.violations.size() && k < 3; ++k)
    s += " " + to_text(w.violations[k], w.H) + ";";
  return s;
}

}  // namespace gmr::checker
