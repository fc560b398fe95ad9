#include "model/scheme/rule_scheme.hpp"

#include <numeric>
#include <set>

#include "model/core/error.hpp"

namespace gmr::scheme {

std::optional<uint32_t> GraphScheme::find(const std::string& name) const {
  for (uint32_t v = 0; v < nodes.size(); ++v)
    if (nodes[v].name == name) return v;
  return std::nullopt;
}

uint32_t GraphScheme::add_node(std::string name, OrbitType label) {
  nodes.push_back(SchemeNode{std::move(name), std::move(label), {}});
  return static_cast<uint32_t>(nodes.size() - 1);
}

void GraphScheme::add_arc(const std::string& a, const std::string& b, int dim) {
  auto va = find(a), vb = find(b);
  if (!va) throw Error(ErrorCode::Schema, "arc names unknown node \"" + a + "\"");
  if (!vb) throw Error(ErrorCode::Schema, "arc names unknown node \"" + b + "\"");
  arcs.push_back(SchemeArc{*va, *vb, dim});
}

size_t GraphScheme::count_explicit(uint32_t v, int d) const {
  size_t c = 0;
  for (const auto& e : arcs)
    if (e.dim == d && (e.a == v || e.b == v)) ++c;
  return c;
}

size_t GraphScheme::count_arcs(uint32_t v, int d) const {
  size_t c = count_explicit(v, d);
  for (int x : nodes[v].label.dims())
    if (x == d) ++c;
  return c;
}

std::optional<uint32_t> GraphScheme::explicit_neighbor(uint32_t v, int d) const {
  std::optional<uint32_t> r;
  for (const auto& e : arcs) {
    if (e.dim != d || (e.a != v && e.b != v)) continue;
    if (r) return std::nullopt;
    r = e.a == v ? e.b : e.a;
  }
  return r;
}

size_t GraphScheme::components(std::vector<uint32_t>& comp) const {
  std::vector<uint32_t> parent(nodes.size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto root = [&](uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& e : arcs)
    if (e.a < nodes.size() && e.b < nodes.size()) parent[root(e.a)] = root(e.b);
  comp.assign(nodes.size(), 0);
  std::vector<int64_t> id(nodes.size(), -1);
  size_t k = 0;
  for (uint32_t v = 0; v < nodes.size(); ++v) {
    const uint32_t r = root(v);
    if (id[r] < 0) id[r] = static_cast<int64_t>(k++);
    comp[v] = static_cast<uint32_t>(id[r]);
  }
  return k;
}

std::optional<uint32_t> RuleScheme::right_of(uint32_t l) const {
  return right.find(left.nodes[l].name);
}
std::optional<uint32_t> RuleScheme::left_of(uint32_t r) const {
  return left.find(right.nodes[r].name);
}
NodeRole RuleScheme::role_left(uint32_t v) const {
  return right_of(v) ? NodeRole::Preserved : NodeRole::Deleted;
}
NodeRole RuleScheme::role_right(uint32_t v) const {
  return left_of(v) ? NodeRole::Preserved : NodeRole::Added;
}

std::vector<uint32_t> RuleScheme::hook_nodes() const {
  std::vector<uint32_t> out;
  for (size_t k = 0; k < hooks.size(); ++k) {
    auto v = left.find(hooks[k]);
    if (!v)
      throw Error(ErrorCode::Schema, "hook \"" + hooks[k] + "\" is not a node of L",
                  "hook " + std::to_string(k));
    out.push_back(*v);
  }
  return out;
}

void RuleScheme::validate_structure() const {
  if (dimension < 0 || dimension >= kMaxDim)
    throw Error(ErrorCode::Schema, "dimension " + std::to_string(dimension) + " out of range 0.." +
                                       std::to_string(kMaxDim - 1));
  for (size_t p = 0; p < orbit.size(); ++p) {
    if (orbit[p] == OrbitType::kHole)
      throw Error(ErrorCode::Schema, "the orbit type of a scheme has no `_`: " + orbit.str(),
                  "orbit");
    if (orbit[p] < 0 || orbit[p] > dimension)
      throw Error(ErrorCode::Schema,
                  "dimension " + std::to_string(orbit[p]) + " of " + orbit.str() + " outside 0.." +
                      std::to_string(dimension),
                  "orbit");
  }
  if (__builtin_popcount(orbit.mask()) != static_cast<int>(orbit.size()))
    throw Error(ErrorCode::Schema, "the orbit type " + orbit.str() + " repeats a dimension",
                "orbit");
  auto side = [&](const GraphScheme& g, const char* tag) {
    std::set<std::string> names;
    for (const auto& nd : g.nodes) {
      const std::string loc = std::string(tag) + " node " + nd.name;
      if (nd.name.empty()) throw Error(ErrorCode::Schema, "empty node name", loc);
      if (!names.insert(nd.name).second) throw Error(ErrorCode::Schema, "duplicate node name", loc);
      if (nd.label.size() != orbit.size())
        throw Error(ErrorCode::Schema,
                    "label " + nd.label.str() + " has arity " + std::to_string(nd.label.size()) +
                        ", the orbit type " + orbit.str() + " has " + std::to_string(orbit.size()),
                    loc);
      for (int x : nd.label.dims())
        if (x != OrbitType::kHole && (x < 0 || x > dimension))
          throw Error(ErrorCode::Schema,
                      "label " + nd.label.str() + " uses dimension " + std::to_string(x) +
                          " outside 0.." + std::to_string(dimension),
                      loc);
    }
    for (size_t k = 0; k < g.arcs.size(); ++k) {
      const auto& e = g.arcs[k];
      const std::string loc = std::string(tag) + " arc " + std::to_string(k);
      if (e.a >= g.nodes.size() || e.b >= g.nodes.size())
        throw Error(ErrorCode::Schema, "arc end out of range", loc);
      if (e.dim < 0 || e.dim > dimension)
        throw Error(
            ErrorCode::Schema,
            "arc dimension " + std::to_string(e.dim) + " outside 0.." + std::to_string(dimension),
            loc);
    }
  };
  side(left, "L");
  side(right, "R");
  std::set<std::string> hs;
  for (size_t k = 0; k < hooks.size(); ++k) {
    if (!left.find(hooks[k]))
      throw Error(ErrorCode::Schema, "hook \"" + hooks[k] + "\" is not a node of L",
                  "hook " + std::to_string(k));
    if (!hs.insert(hooks[k]).second)
      throw Error(ErrorCode::Schema, "hook \"" + hooks[k] + "\" listed twice",
                  "hook " + std::to_string(k));
  }
}

std::string node_label_text(const SchemeNode& n) { return n.name + " " + n.label.str(); }

const EmbeddingDeclaration* RuleScheme::find_embedding(const std::string& embedding) const {
  for (const auto& e : embeddings)
    if (e.name == embedding) return &e;
  return nullptr;
}

}  // namespace gmr::scheme
