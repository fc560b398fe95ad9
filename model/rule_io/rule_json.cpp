#include "model/rule_io/rule_json.hpp"

#include <map>

#include "model/core/error.hpp"
#include "model/map_io/atomic_write.hpp"
#include "model/map_io/json_reader.hpp"
#include "model/map_io/read_file.hpp"

namespace gmr::io {
using namespace gmr::graph;
using namespace gmr::rewrite;

namespace {

DGraph read_side(const JsonAt& side, int lo, int n) {
  side.require_object();
  side.allow_only({"nodes", "arcs", "links"});
  DGraph g;
  std::map<std::string, Node> ids;
  const JsonAt nodes = side["nodes"];
  for (size_t k = 0; k < nodes.array_size(); ++k) {
    const JsonAt v = nodes[k];
    const std::string name = v.as_string();
    if (name.empty()) v.fail("node names must not be empty");
    if (ids.count(name)) v.fail("duplicate node name \"" + name + "\"");
    ids[name] = g.add_node(name);
  }
  auto node_of = [&](const JsonAt& v) {
    const std::string name = v.as_string();
    auto it = ids.find(name);
    if (it == ids.end()) v.fail("unknown node \"" + name + "\" (not listed in \"nodes\")");
    return it->second;
  };
  auto label_of = [&](const JsonAt& v) {
    if (!v.value().is_number_integer())
      v.fail("expected an integer label, found " + describe_json(v.value()));
    const auto l = v.value().get<int64_t>();
    if (l < lo || l > n)
      v.fail("label " + std::to_string(l) + " outside the dimension set " + std::to_string(lo) +
             ".." + std::to_string(n));
    return static_cast<int>(l);
  };
  if (auto arcs = side.get("arcs")) {
    for (size_t k = 0; k < arcs->array_size(); ++k) {
      const JsonAt a = (*arcs)[k];
      a.require_object();
      a.allow_only({"from", "to", "label"});
      const Node s = node_of(a["from"]);
      const Node t = node_of(a["to"]);
      g.add_arc(s, t, label_of(a["label"]));
    }
  }
  if (auto links = side.get("links")) {
    for (size_t k = 0; k < links->array_size(); ++k) {
      const JsonAt a = (*links)[k];
      a.require_object();
      a.allow_only({"nodes", "label"});
      const JsonAt ends = a["nodes"];
      if (ends.array_size() != 2)
        ends.fail("a link has exactly two nodes (the same twice for a loop)");
      const Node s = node_of(ends[0]);
      const Node t = node_of(ends[1]);
      g.add_link(s, t, label_of(a["label"]));
    }
  }
  return g;
}

nlohmann::ordered_json side_to_json(const DGraph& g) {
  nlohmann::ordered_json j;
  j["nodes"] = nlohmann::ordered_json::array();
  for (Node v : g.nodes()) j["nodes"].push_back(g.name(v));
  j["arcs"] = nlohmann::ordered_json::array();
  for (ArcId a : g.arc_slots())
    if (g.arc_alive(a))
      j["arcs"].push_back({{"from", g.name(g.arc(a).src)},
                           {"to", g.name(g.arc(a).tgt)},
                           {"label", g.arc(a).label}});
  return j;
}

}  // namespace

Rule rule_from_json(const nlohmann::json& doc, const std::string& source) {
  const JsonAt root(doc, source);
  root.check_header("gmr.rule", 1);
  root.allow_only(
      {"format", "version", "kind", "name", "description", "map", "n", "left", "right"});
  const JsonAt kind = root["kind"];
  if (kind.as_string() != "concrete")
    kind.fail("unsupported rule kind \"" + kind.as_string() +
              "\" (this reader knows \"concrete\")");
  std::string name;
  if (auto nm = root.get("name")) name = nm->as_string();
  if (auto d = root.get("description")) (void)d->as_string();
  const JsonAt map = root["map"];
  const std::string ms = map.as_string();
  MapKind mk;
  if (ms == "gmap")
    mk = MapKind::GMap;
  else if (ms == "omap")
    mk = MapKind::OMap;
  else
    map.fail("expected \"gmap\" or \"omap\", found \"" + ms + "\"");
  const int lo = MapSpec{0, mk}.lowest_dim();
  const int n = static_cast<int>(root["n"].as_int(lo, kMaxDim - 1));
  DGraph L = read_side(root["left"], lo, n);
  DGraph R = read_side(root["right"], lo, n);
  try {
    return Rule(std::move(L), std::move(R), n, mk, name);
  } catch (const Error& e) {  // cannot happen after the checks above; keep the location anyway
    throw Error(e.code(), e.message(), root.location_of("$." + e.location()));
  }
}

Rule parse_rule(std::string_view text, const std::string& source) {
  const nlohmann::json doc = parse_json(text, source);
  return rule_from_json(doc, source);
}

Rule read_rule_file(const std::filesystem::path& path) {
  return parse_rule(read_text_file(path), path.string());
}

nlohmann::ordered_json rule_to_json(const Rule& r) {
  nlohmann::ordered_json j;
  j["format"] = "gmr.rule";
  j["version"] = 1;
  j["kind"] = "concrete";
  if (!r.name().empty()) j["name"] = r.name();
  j["map"] = r.kind() == MapKind::OMap ? "omap" : "gmap";
  j["n"] = r.dimension();
  j["left"] = side_to_json(r.left());
  j["right"] = side_to_json(r.right());
  return j;
}

void write_rule_file(const Rule& r, const std::filesystem::path& path) {
  write_file_atomic(path, rule_to_json(r).dump(2) + "\n");
}

}  // namespace gmr::io
