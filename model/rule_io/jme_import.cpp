#include "model/rule_io/jme_import.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <map>

#include "model/core/error.hpp"
#include "model/expr/compiled_scheme.hpp"
#include "model/map_io/read_file.hpp"
#include "model/rule_io/jme_expression.hpp"
#include "model/rule_io/xml.hpp"

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
    if (item.empty() || ec != std::errc() || ptr != item.data() + item.size() || v < -1 ||
        v >= kMaxDim)
      throw Error(ErrorCode::Parse, "bad Jerboa orbit \"" + std::string(text) + "\"");
    dims.push_back(v == -1 ? OrbitType::kHole : v);
    p = c + 1;
  }
  return OrbitType(std::move(dims));
}

namespace {

using tinyxml2::XMLElement;

struct Ctx {
  const XmlDocument& doc;
  std::string at(const XMLElement& e) const { return doc.at(e); }
  std::string attr(const XMLElement& e, const char* key) const {
    const char* v = e.Attribute(key);
    if (!v)
      throw Error(ErrorCode::Schema, "<" + std::string(e.Name()) + "> has no attribute " + key,
                  at(e));
    return v;
  }
  int integer(const XMLElement& e, const char* key, int lo, int hi) const {
    const std::string s = attr(e, key);
    int v = 0;
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || ec != std::errc() || ptr != s.data() + s.size() || v < lo || v > hi)
      throw Error(ErrorCode::Schema,
                  "attribute " + std::string(key) + "=\"" + s + "\" is not an integer in " +
                      std::to_string(lo) + ".." + std::to_string(hi),
                  at(e));
    return v;
  }
  const XMLElement& child(const XMLElement& e, const char* name) const {
    const XMLElement* c = e.FirstChildElement(name);
    if (!c)
      throw Error(ErrorCode::Schema, "<" + std::string(e.Name()) + "> has no <" + name + ">",
                  at(e));
    return *c;
  }
};

void read_side(const Ctx& cx, const XMLElement& side, GraphScheme& g,
               std::vector<std::string>* hooks) {
  for (const XMLElement* nodes : xml_children(side, "nodes"))
    for (const XMLElement* n : xml_children(*nodes, "node")) {
      OrbitType label;
      try {
        label = parse_jme_orbit(cx.attr(*n, "orbit"));
      } catch (const Error& e) {
        throw Error(ErrorCode::Schema, e.message(), cx.at(*n));
      }
      const std::string name = cx.attr(*n, "name");
      // Duplicate names are kept (the checker reports them): add_node does not refuse them.
      const uint32_t id = g.add_node(name, std::move(label));
      for (const XMLElement* ex : xml_children(*n, "expr"))
        g.nodes[id].expressions.push_back({cx.attr(*ex, "ebd"), xml_text(*ex), {}, {}});
      if (n->Attribute("kind", "HOOK")) {
        if (!hooks) throw Error(ErrorCode::Schema, "a hook in the right-hand side", cx.at(*n));
        hooks->push_back(name);
      }
    }
  auto node = [&](const XMLElement& e, const char* key) {
    const std::string nm = cx.attr(e, key);
    auto id = g.find(nm);
    if (!id) throw Error(ErrorCode::Schema, "arc names unknown node \"" + nm + "\"", cx.at(e));
    return *id;
  };
  for (const XMLElement* arcs : xml_children(side, "arcs"))
    for (const XMLElement* a : xml_children(*arcs)) {
      const std::string_view kind = a->Name();
      if (kind == "arc") {
        const int d = cx.integer(*a, "dim", 0, kMaxDim - 1);
        g.arcs.push_back(SchemeArc{node(*a, "a"), node(*a, "b"), d});
      } else if (kind == "arcloop") {
        const int d = cx.integer(*a, "dim", 0, kMaxDim - 1);
        const uint32_t v = node(*a, "node");
        g.arcs.push_back(SchemeArc{v, v, d});
      } else {
        throw Error(ErrorCode::Schema, "unexpected <" + std::string(kind) + "> in <arcs>",
                    cx.at(*a));
      }
    }
}

// Each right-hand expression translated into gmr's language (jme_expression.hpp) and checked in
// the rule's context; the Java code is kept in `jerboa`, and an expression that does not translate
// or check gets `unsupported` (the reason) and no code.
void translate_expressions(RuleScheme& s) {
  std::vector<expr::EmbeddingSignature> sigs;
  try {
    sigs = expr::embedding_signatures(s);
  } catch (const Error&) {
    // an unknown embedding type: expressions for it are reported below
  }
  const expr::CheckContext ctx = expr::check_context(s, sigs);
  for (auto& n : s.right.nodes)
    for (auto& x : n.expressions) {
      x.jerboa = x.code;
      x.code.clear();
      const JerboaTranslation t = translate_jerboa_expression(x.jerboa);
      if (!t.code) {
        x.unsupported = t.unsupported;
        continue;
      }
      const expr::EmbeddingSignature* sig = nullptr;
      for (const auto& g : sigs)
        if (g.name == x.embedding) sig = &g;
      if (!sig) {
        x.unsupported = "no declared embedding '" + x.embedding + "' of a known type";
        continue;
      }
      try {
        expr::compile_expression(*t.code, *sig, ctx, "");
        x.code = *t.code;
      } catch (const Error& e) {
        x.unsupported = "translated to '" + *t.code + "', which does not check: " + e.message();
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
  const XmlDocument doc(text, source);
  const Ctx cx{doc};
  const XMLElement& root = doc.root();
  const XMLElement* modeler =
      std::string_view(root.Name()) == "modeler" ? &root : root.FirstChildElement("modeler");
  if (!modeler)
    throw Error(ErrorCode::Schema, "no <modeler> element (not a Jerboa .jme file)", cx.at(root));
  JmeModeler m;
  if (const char* nm = modeler->Attribute("name")) m.name = nm;
  m.dimension = cx.integer(*modeler, "dimension", 0, kMaxDim - 1);
  if (const XMLElement* ebds = modeler->FirstChildElement("embeddings"))
    for (const XMLElement* e : xml_children(*ebds, "embedding")) {
      JmeEmbedding je;
      je.name = cx.attr(*e, "name");
      if (const char* t = e->Attribute("type")) je.type = t;
      try {
        je.orbit = parse_jme_orbit(cx.attr(*e, "orbit"));
      } catch (const Error& err) {
        throw Error(ErrorCode::Schema, err.message(), cx.at(*e));
      }
      m.embeddings.push_back(std::move(je));
    }
  const XMLElement& rules = cx.child(*modeler, "rules");
  for (const XMLElement* r : xml_children(rules, "rule")) {
    RuleScheme s;
    s.name = cx.attr(*r, "name");
    for (size_t k = 0; k < m.rules.size(); ++k)
      if (m.rules[k].name == s.name)
        throw Error(ErrorCode::Schema,
                    "two rules named \"" + s.name + "\" (lines " + std::to_string(m.rule_lines[k]) +
                        " and " + std::to_string(r->GetLineNum()) +
                        "): --rule could not tell them apart",
                    cx.at(*r));
    s.dimension = m.dimension;
    if (const XMLElement* c = r->FirstChildElement("comment"))
      s.description = trimmed(xml_text(*c));
    if (const XMLElement* p = r->FirstChildElement("precondition"))
      s.precondition = trimmed(xml_text(*p));
    std::vector<std::string> hooks;
    read_side(cx, cx.child(*r, "left"), s.left, &hooks);
    read_side(cx, cx.child(*r, "right"), s.right, nullptr);
    // Hook order: <paramtopo order=..>.
    std::map<std::string, int> order;
    if (const XMLElement* pt = r->FirstChildElement("paramstopo"))
      for (const XMLElement* p : xml_children(*pt, "paramtopo"))
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
    for (const auto& e : m.embeddings) {
      const auto t = expr::parse_value_type(e.type);
      s.embeddings.push_back({e.name, e.orbit, t ? expr::to_string(*t) : e.type});
    }
    translate_expressions(s);
    m.rules.push_back(std::move(s));
    m.rule_lines.push_back(static_cast<size_t>(r->GetLineNum()));
  }
  return m;
}

JmeModeler read_jme_file(const std::filesystem::path& path) {
  return parse_jme(read_text_file(path), path.string());
}

}  // namespace gmr::io
