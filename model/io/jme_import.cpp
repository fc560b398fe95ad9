#include "model/io/jme_import.hpp"

#include <algorithm>
#include <charconv>
#include <map>

#include "model/core/error.hpp"
#include "model/io/read_file.hpp"
#include "model/io/xml.hpp"

namespace gmr::io {
 using namespace gmr::scheme;

OrbitType parse_jme_orbit(std::string_view text) {
  std::vector<int> dims;
  size_t p = 0;
  auto trim = [](std::string_view s) {
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
    return s;
  };
  if (trim(text).empty()) return OrbitType{};
  while (p <= text.size()) {
    size_t c = text.find(',', p);
    if (c == std::string_view::npos) c = text.size();
    const std::string_view item = trim(text.substr(p, c - p));
    int v = 0;
    auto [ptr, ec] = std::from_chars(item.data(), item.data() + item.size(), v);
    if (item.empty() || ec != std::errc() || ptr != item.data() + item.size() || v < -1 || v >= kMaxDim)
      throw Error(ErrorCode::Parse, "bad Jerboa orbit \"" + std::string(text) + "\"");
    dims.push_back(v == -1 ? OrbitType::kHole : v);
    p = c + 1;
  }
  return OrbitType(std::move(dims));
}

namespace {

struct Ctx {
  const std::string& source;
  std::string at(const XmlElement& e) const {
    return source.empty() ? "line " + std::to_string(e.line) : source + ":" + std::to_string(e.line);
  }
  const std::string& attr(const XmlElement& e, const char* key) const {
    const std::string* v = e.attribute(key);
    if (!v) throw Error(ErrorCode::Schema, "<" + e.name + "> has no attribute " + key, at(e));
    return *v;
  }
  int integer(const XmlElement& e, const char* key, int lo, int hi) const {
    const std::string& s = attr(e, key);
    int v = 0;
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || ec != std::errc() || ptr != s.data() + s.size() || v < lo || v > hi)
      throw Error(ErrorCode::Schema,
                  "attribute " + std::string(key) + "=\"" + s + "\" is not an integer in " + std::to_string(lo) +
                      ".." + std::to_string(hi),
                  at(e));
    return v;
  }
  const XmlElement& child(const XmlElement& e, const char* name) const {
    const XmlElement* c = e.child(name);
    if (!c) throw Error(ErrorCode::Schema, "<" + e.name + "> has no <" + name + ">", at(e));
    return *c;
  }
};

void read_side(const Ctx& cx, const XmlElement& side, GraphScheme& g, std::vector<std::string>* hooks) {
  for (const XmlElement* nodes : side.children_named("nodes"))
    for (const XmlElement* n : nodes->children_named("node")) {
      OrbitType label;
      try {
        label = parse_jme_orbit(cx.attr(*n, "orbit"));
      } catch (const Error& e) {
        throw Error(ErrorCode::Schema, e.message(), cx.at(*n));
      }
      const std::string& name = cx.attr(*n, "name");
      // Duplicate names are kept (the checker reports them): add_node does not refuse them.
      const uint32_t id = g.add_node(name, std::move(label));
      for (const XmlElement* ex : n->children_named("expr"))
        g.nodes[id].expressions.push_back({cx.attr(*ex, "ebd"), ex->text});
      const std::string* kind = n->attribute("kind");
      if (kind && *kind == "HOOK") {
        if (!hooks) throw Error(ErrorCode::Schema, "a hook in the right-hand side", cx.at(*n));
        hooks->push_back(name);
      }
    }
  auto node = [&](const XmlElement& e, const char* key) {
    const std::string& nm = cx.attr(e, key);
    auto id = g.find(nm);
    if (!id) throw Error(ErrorCode::Schema, "arc names unknown node \"" + nm + "\"", cx.at(e));
    return *id;
  };
  for (const XmlElement* arcs : side.children_named("arcs"))
    for (const auto& a : arcs->children) {
      if (a->name == "arc") {
        const int d = cx.integer(*a, "dim", 0, kMaxDim - 1);
        g.arcs.push_back(SchemeArc{node(*a, "a"), node(*a, "b"), d});
      } else if (a->name == "arcloop") {
        const int d = cx.integer(*a, "dim", 0, kMaxDim - 1);
        const uint32_t v = node(*a, "node");
        g.arcs.push_back(SchemeArc{v, v, d});
      } else {
        throw Error(ErrorCode::Schema, "unexpected <" + a->name + "> in <arcs>", cx.at(*a));
      }
    }
}

std::string trimmed(const std::string& s) {
  size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

}  // namespace

JmeModeler parse_jme(std::string_view text, const std::string& source) {
  const XmlElement doc = parse_xml(text, source);
  const Ctx cx{source};
  const XmlElement* modeler = doc.name == "modeler" ? &doc : doc.child("modeler");
  if (!modeler) throw Error(ErrorCode::Schema, "no <modeler> element (not a Jerboa .jme file)", cx.at(doc));
  JmeModeler m;
  if (const std::string* nm = modeler->attribute("name")) m.name = *nm;
  m.dimension = cx.integer(*modeler, "dimension", 0, kMaxDim - 1);
  if (const XmlElement* ebds = modeler->child("embeddings"))
    for (const XmlElement* e : ebds->children_named("embedding")) {
      JmeEmbedding je;
      je.name = cx.attr(*e, "name");
      if (const std::string* t = e->attribute("type")) je.type = *t;
      try {
        je.orbit = parse_jme_orbit(cx.attr(*e, "orbit"));
      } catch (const Error& err) {
        throw Error(ErrorCode::Schema, err.message(), cx.at(*e));
      }
      m.embeddings.push_back(std::move(je));
    }
  const XmlElement& rules = cx.child(*modeler, "rules");
  for (const XmlElement* r : rules.children_named("rule")) {
    RuleScheme s;
    s.name = cx.attr(*r, "name");
    s.dimension = m.dimension;
    if (const XmlElement* c = r->child("comment")) s.description = trimmed(c->text);
    if (const XmlElement* p = r->child("precondition")) s.precondition = trimmed(p->text);
    std::vector<std::string> hooks;
    read_side(cx, cx.child(*r, "left"), s.left, &hooks);
    read_side(cx, cx.child(*r, "right"), s.right, nullptr);
    // Hook order: <paramtopo order=..>.
    std::map<std::string, int> order;
    if (const XmlElement* pt = r->child("paramstopo"))
      for (const XmlElement* p : pt->children_named("paramtopo"))
        order[cx.attr(*p, "name")] = cx.integer(*p, "order", 0, 1 << 20);
    std::stable_sort(hooks.begin(), hooks.end(), [&](const std::string& a, const std::string& b) {
      const int oa = order.count(a) ? order[a] : 1 << 21, ob = order.count(b) ? order[b] : 1 << 21;
      return oa < ob;
    });
    s.hooks = hooks;
    if (!hooks.empty()) {
      s.orbit = s.left.nodes[*s.left.find(hooks[0])].label;
    } else {
      const GraphScheme& side = s.left.size() ? s.left : s.right;
      if (side.size() && !side.nodes[0].label.has_hole()) s.orbit = side.nodes[0].label;
    }
    m.rules.push_back(std::move(s));
    m.rule_lines.push_back(r->line);
  }
  return m;
}

JmeModeler read_jme_file(const std::filesystem::path& path) {
  return parse_jme(read_text_file(path), path.string());
}

}  // namespace gmr::io
