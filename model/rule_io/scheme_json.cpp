#include "model/rule_io/scheme_json.hpp"

#include <set>

#include "model/core/error.hpp"
#include "model/expr/compiled_scheme.hpp"
#include "model/map_io/atomic_write.hpp"
#include "model/map_io/json_reader.hpp"
#include "model/map_io/json_writer.hpp"
#include "model/map_io/read_file.hpp"

namespace gmr::io {
using namespace gmr::scheme;

namespace {

OrbitType read_orbit(const JsonAt& v) {
  const std::string text = v.as_string();
  try {
    return OrbitType::parse(text);
  } catch (const Error& e) {
    v.fail(e.message(), ErrorCode::Schema);
  }
}

GraphScheme read_side(const JsonAt& side, const RuleScheme& r) {
  side.require_object();
  side.allow_only({"nodes", "arcs"});
  GraphScheme g;
  const JsonAt nodes = side["nodes"];
  for (size_t k = 0; k < nodes.array_size(); ++k) {
    const JsonAt v = nodes[k];
    v.require_object();
    v.allow_only({"name", "orbit", "expressions"});
    const JsonAt nm = v["name"];
    const std::string name = nm.as_string();
    if (name.empty()) nm.fail("node names must not be empty");
    if (g.find(name)) nm.fail("duplicate node name \"" + name + "\"");
    const JsonAt ov = v["orbit"];
    OrbitType label = read_orbit(ov);
    if (label.size() != r.orbit.size())
      ov.fail("label " + label.str() + " has arity " + std::to_string(label.size()) +
              ", the scheme's orbit " + r.orbit.str() + " has " + std::to_string(r.orbit.size()));
    for (int x : label.dims())
      if (x != OrbitType::kHole && x > r.dimension)
        ov.fail("label " + label.str() + " uses dimension " + std::to_string(x) + " outside 0.." +
                std::to_string(r.dimension));
    const uint32_t id = g.add_node(name, std::move(label));
    if (auto ex = v.get("expressions")) {
      for (size_t e = 0; e < ex->array_size(); ++e) {
        const JsonAt x = (*ex)[e];
        x.require_object();
        x.allow_only({"embedding", "code", "jerboa", "unsupported"});
        scheme::EmbeddingExpression ee{x["embedding"].as_string(), {}, {}, {}};
        if (auto u = x.get("unsupported")) ee.unsupported = u->as_string();
        if (auto j = x.get("jerboa")) ee.jerboa = j->as_string();
        if (ee.unsupported.empty())
          ee.code = x["code"].as_string();
        else if (auto c = x.get("code"))
          c->fail("an unsupported Jerboa expression has no code");
        g.nodes[id].expressions.push_back(std::move(ee));
      }
    }
  }
  if (auto arcs = side.get("arcs")) {
    for (size_t k = 0; k < arcs->array_size(); ++k) {
      const JsonAt a = (*arcs)[k];
      a.require_object();
      a.allow_only({"nodes", "label"});
      const JsonAt ends = a["nodes"];
      if (ends.array_size() != 2)
        ends.fail("an arc has exactly two nodes (the same twice for a loop)");
      uint32_t e[2];
      for (size_t t = 0; t < 2; ++t) {
        const std::string n = ends[t].as_string();
        auto id = g.find(n);
        if (!id) ends[t].fail("unknown node \"" + n + "\" (not listed in \"nodes\")");
        e[t] = *id;
      }
      const int dim = static_cast<int>(a["label"].as_int(0, r.dimension));
      g.arcs.push_back(SchemeArc{e[0], e[1], dim});
    }
  }
  return g;
}

// Every expression parsed and type-checked (docs/embeddings.md), errors located by JSON path, rule
// and node, and column in the code.
void check_expressions(const JsonAt& root, const RuleScheme& r) {
  const auto sigs = expr::embedding_signatures(r);
  const auto ctx = expr::check_context(r, sigs);
  auto side_check = [&](const char* key, const GraphScheme& g, bool right) {
    const JsonAt nodes = root[key]["nodes"];
    for (uint32_t v = 0; v < g.size(); ++v) {
      const auto& xs = g.nodes[v].expressions;
      if (xs.empty()) continue;
      const JsonAt ex = nodes[v]["expressions"];
      if (!right) {
        if (!r.right_of(v))
          ex.fail("an expression on a deleted node: expressions belong to right-hand nodes");
        continue;  // kept, the right-hand node's expression is the one applied
      }
      for (size_t k = 0; k < xs.size(); ++k) {
        const JsonAt x = ex[k];
        if (!xs[k].unsupported.empty()) continue;  // an untranslated Jerboa expression
        const auto* decl = r.find_embedding(xs[k].embedding);
        if (!decl)
          x["embedding"].fail("embedding \"" + xs[k].embedding +
                              "\" is not declared in \"embeddings\"");
        for (size_t j = 0; j < k; ++j)
          if (xs[j].embedding == xs[k].embedding)
            x["embedding"].fail("two expressions for embedding \"" + xs[k].embedding +
                                "\" on node " + g.nodes[v].name + " (thesis Def. 71: at most one)");
        size_t e = 0;
        while (sigs[e].name != decl->name) ++e;
        const std::string where = x.location_of(x.child_path("code")) + " (rule " + r.name +
                                  ", node " + g.nodes[v].name + ")";
        expr::compile_expression(xs[k].code, sigs[e], ctx, where);
      }
    }
  };
  side_check("left", r.left, false);
  side_check("right", r.right, true);
}

nlohmann::ordered_json side_to_json(const GraphScheme& g) {
  nlohmann::ordered_json j;
  j["nodes"] = nlohmann::ordered_json::array();
  for (const auto& n : g.nodes) {
    nlohmann::ordered_json v;
    v["name"] = n.name;
    v["orbit"] = n.label.str();
    if (!n.expressions.empty()) {
      v["expressions"] = nlohmann::ordered_json::array();
      for (const auto& e : n.expressions) {
        nlohmann::ordered_json x;
        x["embedding"] = e.embedding;
        if (e.unsupported.empty()) x["code"] = e.code;
        if (!e.jerboa.empty()) x["jerboa"] = e.jerboa;
        if (!e.unsupported.empty()) x["unsupported"] = e.unsupported;
        v["expressions"].push_back(std::move(x));
      }
    }
    j["nodes"].push_back(std::move(v));
  }
  j["arcs"] = nlohmann::ordered_json::array();
  for (const auto& e : g.arcs)
    j["arcs"].push_back({{"nodes", {g.nodes[e.a].name, g.nodes[e.b].name}}, {"label", e.dim}});
  return j;
}

}  // namespace

std::string rule_document_kind(const nlohmann::json& doc, const std::string& source) {
  const JsonAt root(doc, source);
  root.check_header("gmr.rule", 1);
  return root["kind"].as_string();
}

RuleScheme scheme_from_json(const nlohmann::json& doc, const std::string& source) {
  const JsonAt root(doc, source);
  root.check_header("gmr.rule", 1);
  root.allow_only({"format", "version", "kind", "name", "description", "map", "n", "orbit", "hooks",
                   "left", "right", "precondition", "embeddings"});
  const JsonAt kind = root["kind"];
  if (kind.as_string() != "scheme")
    kind.fail("expected kind \"scheme\", found \"" + kind.as_string() + "\"");
  RuleScheme r;
  if (auto nm = root.get("name")) r.name = nm->as_string();
  if (auto d = root.get("description")) r.description = d->as_string();
  if (auto p = root.get("precondition")) r.precondition = p->as_string();
  const JsonAt map = root["map"];
  if (map.as_string() != "gmap")
    map.fail("rule schemes rewrite G-maps: expected \"gmap\", found \"" + map.as_string() + "\"");
  r.dimension = static_cast<int>(root["n"].as_int(0, kMaxDim - 1));
  const JsonAt ov = root["orbit"];
  r.orbit = read_orbit(ov);
  std::set<int> seen;
  for (int x : r.orbit.dims()) {
    if (x == OrbitType::kHole) ov.fail("the orbit of a scheme has no `_`: " + r.orbit.str());
    if (x > r.dimension)
      ov.fail("dimension " + std::to_string(x) + " outside 0.." + std::to_string(r.dimension));
    if (!seen.insert(x).second)
      ov.fail("dimension " + std::to_string(x) + " repeated in " + r.orbit.str());
  }
  if (auto em = root.get("embeddings")) {
    for (size_t k = 0; k < em->array_size(); ++k) {
      const JsonAt d = (*em)[k];
      d.require_object();
      d.allow_only({"name", "orbit", "type"});
      scheme::EmbeddingDeclaration decl{d["name"].as_string(), read_orbit(d["orbit"]),
                                        d["type"].as_string()};
      if (decl.name.empty()) d["name"].fail("embedding names must not be empty");
      if (!expr::parse_value_type(decl.type))
        d["type"].fail("unknown value type \"" + decl.type + "\" (point, vector, scalar, colour)");
      for (int x : decl.orbit.dims())
        if (x == OrbitType::kHole || x > r.dimension)
          d["orbit"].fail("an embedding's orbit type uses dimensions 0.." +
                          std::to_string(r.dimension) + " without `_`");
      if (r.find_embedding(decl.name))
        d["name"].fail("embedding \"" + decl.name + "\" declared twice");
      r.embeddings.push_back(std::move(decl));
    }
  }
  r.left = read_side(root["left"], r);
  r.right = read_side(root["right"], r);
  const JsonAt hooks = root["hooks"];
  for (size_t k = 0; k < hooks.array_size(); ++k) {
    const std::string h = hooks[k].as_string();
    if (!r.left.find(h)) hooks[k].fail("hook \"" + h + "\" is not a node of \"left\"");
    for (const auto& prev : r.hooks)
      if (prev == h) hooks[k].fail("hook \"" + h + "\" listed twice");
    r.hooks.push_back(h);
  }
  check_expressions(root, r);
  return r;
}

RuleScheme parse_scheme(std::string_view text, const std::string& source) {
  return scheme_from_json(parse_json(text, source), source);
}

RuleScheme read_scheme_file(const std::filesystem::path& path) {
  return parse_scheme(read_text_file(path), path.string());
}

nlohmann::ordered_json scheme_to_json(const RuleScheme& s) {
  nlohmann::ordered_json j;
  j["format"] = "gmr.rule";
  j["version"] = 1;
  j["kind"] = "scheme";
  if (!s.name.empty()) j["name"] = s.name;
  if (!s.description.empty()) j["description"] = s.description;
  j["map"] = "gmap";
  j["n"] = s.dimension;
  j["orbit"] = s.orbit.str();
  if (!s.embeddings.empty()) {
    j["embeddings"] = nlohmann::ordered_json::array();
    for (const auto& d : s.embeddings)
      j["embeddings"].push_back({{"name", d.name}, {"orbit", d.orbit.str()}, {"type", d.type}});
  }
  j["hooks"] = s.hooks;
  j["left"] = side_to_json(s.left);
  j["right"] = side_to_json(s.right);
  if (!s.precondition.empty()) j["precondition"] = s.precondition;
  return j;
}

std::string scheme_to_json_text(const RuleScheme& s) { return dump_json(scheme_to_json(s)) + "\n"; }

void write_scheme_file(const RuleScheme& s, const std::filesystem::path& path) {
  write_file_atomic(path, scheme_to_json_text(s));
}

}  // namespace gmr::io
