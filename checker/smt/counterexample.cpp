#include "checker/smt/counterexample.hpp"

#include <charconv>
#include <set>

#include "model/draw/map_dot.hpp"
#include "model/map_io/map_json.hpp"

namespace gmr::smt {
using graph::ArcId;
using graph::Node;

namespace {
// H keeps the names of G's nodes (the dart indices, graph::to_dgraph); added nodes are primed.
std::optional<Dart> dart_of(const DGraph& H, Node x) {
  const std::string& s = H.name(x);
  Dart d = 0;
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), d);
  if (ec != std::errc() || p != s.data() + s.size()) return std::nullopt;
  return d;
}
}  // namespace

std::vector<Dart> offending_darts(const Counterexample& c) {
  std::set<Dart> out;
  for (const auto& v : c.violations)
    if (auto d = dart_of(c.H, Node(v.at))) out.insert(*d);
  return {out.begin(), out.end()};
}

nlohmann::ordered_json to_json(const Rule& r, unsigned bound, const Counterexample& c) {
  nlohmann::ordered_json j;
  j["format"] = kCounterexampleFormat;
  j["version"] = kCounterexampleVersion;
  j["rule"] = r.name();
  j["engine"] = to_string(c.engine);
  j["bound"] = bound;
  j["G"] = io::map_to_json(c.G);
  j["gluing_fails"] =
      c.gluing_fails;  // the match fails the gluing condition (consistency semantics; no H)
  nlohmann::ordered_json m = nlohmann::ordered_json::object();
  for (Node v : r.left().nodes()) m[r.left().name(v)] = graph::dart_of(c.match.node[v]);
  j["match"] = m;
  nlohmann::ordered_json h;
  h["nodes"] = nlohmann::ordered_json::array();
  for (Node x : c.H.nodes()) h["nodes"].push_back(c.H.node_str(x));
  h["arcs"] = nlohmann::ordered_json::array();
  for (ArcId a : c.H.arc_slots()) {
    if (!c.H.arc_alive(a)) continue;
    const auto& arc = c.H.arc(a);
    h["arcs"].push_back({{"source", c.H.node_str(arc.src)},
                         {"target", c.H.node_str(arc.tgt)},
                         {"label", arc.label}});
  }
  j["H"] = h;
  j["violations"] = nlohmann::ordered_json::array();
  for (const auto& v : c.violations) {
    nlohmann::ordered_json e;
    e["constraint"] = symbol(v.constraint);
    e["node"] = c.H.node_str(Node(v.at));
    e["i"] = v.i;
    if (v.j >= 0) e["j"] = v.j;
    e["text"] = graph::to_text(v, c.H);
    j["violations"].push_back(e);
  }
  j["offending_darts"] = offending_darts(c);
  return j;
}

std::string to_dot(const Rule& r, const Counterexample& c) {
  draw::DotOptions opt;
  opt.loops = true;
  opt.name = "counterexample";
  std::string dot = draw::to_dot(c.G, opt);
  const auto bad = offending_darts(c);
  std::string extra =
      "  // matched darts light blue (xlabel: L node), darts where H breaks a constraint red\n";
  std::set<Dart> matched;
  for (Node v : r.left().nodes()) {
    const Dart d = graph::dart_of(c.match.node[v]);
    matched.insert(d);
    const bool b = std::find(bad.begin(), bad.end(), d) != bad.end();
    extra += "  " + std::to_string(d) + " [style=filled, fillcolor=\"" +
             (b ? "#ff6b6b" : "#a6cee3") + "\", xlabel=" + nlohmann::json(r.left().name(v)).dump() +
             "];\n";
  }
  for (Dart d : bad)
    if (!matched.count(d))
      extra += "  " + std::to_string(d) + " [style=filled, fillcolor=\"#ff6b6b\"];\n";
  dot.insert(dot.rfind('}'), extra);
  return dot;
}

nlohmann::ordered_json verdict_json(const VerifyResult& v) {
  nlohmann::ordered_json j;
  j["engine"] = to_string(v.engine);
  j["bound"] = v.bound;
  j["verdict"] = v.preserves ? "preserves" : "breaks";
  j["applicable"] = v.applicable;
  j["seconds"] = v.seconds;
  return j;
}

}  // namespace gmr::smt
