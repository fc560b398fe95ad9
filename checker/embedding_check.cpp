#include "checker/embedding_check.hpp"

#include <map>
#include <numeric>
#include <set>

#include "model/core/error.hpp"
#include "model/expr/compiled_scheme.hpp"

namespace gmr::checker {
using namespace gmr::scheme;

namespace {

// Classes of one side's nodes over its explicit arcs whose dimension is in `mask`.
std::vector<uint32_t> classes(const GraphScheme& g, DimMask mask) {
  std::vector<uint32_t> p(g.size());
  std::iota(p.begin(), p.end(), 0u);
  auto find = [&](uint32_t x) {
    while (p[x] != x) x = p[x] = p[p[x]];
    return x;
  };
  for (const auto& a : g.arcs)
    if (mask >> a.dim & 1u) {
      const uint32_t x = find(a.a), y = find(a.b);
      if (x != y) p[std::max(x, y)] = std::min(x, y);
    }
  for (uint32_t v = 0; v < g.size(); ++v) p[v] = find(v);
  return p;
}

}  // namespace

bool check_embeddings(const RuleScheme& s, std::vector<Diagnostic>& out) {
  const size_t before = out.size();
  auto add = [&](const char* code, Severity sev, std::vector<std::string> nodes, std::string msg) {
    out.push_back(Diagnostic{.code = code,
                             .severity = sev,
                             .condition = "embeddings",
                             .side = Side::R,
                             .nodes = std::move(nodes),
                             .message = std::move(msg)});
  };
  std::vector<expr::EmbeddingSignature> sigs;
  for (const auto& d : s.embeddings) {
    RuleScheme one = s;
    one.embeddings = {d};
    try {
      const auto sig = expr::embedding_signatures(one);
      bool twice = false;
      for (const auto& x : sigs) twice |= x.name == d.name;
      if (twice) {
        add("E-declaration", Severity::Error, {}, "embedding '" + d.name + "' declared twice");
        continue;
      }
      sigs.push_back(sig[0]);
    } catch (const Error& e) {
      add("E-declaration", Severity::Error, {}, "embedding '" + d.name + "': " + e.message());
    }
  }
  const expr::CheckContext ctx = expr::check_context(s, sigs);
  // compiled[e][v]: the expression of R node v for signature e (nullptr: none or malformed).
  std::vector<std::vector<std::shared_ptr<const expr::Expr>>> compiled(
      sigs.size(), std::vector<std::shared_ptr<const expr::Expr>>(s.right.size()));
  std::vector<std::vector<bool>> written(sigs.size(), std::vector<bool>(s.right.size(), false));
  for (uint32_t v = 0; v < s.right.size(); ++v) {
    const std::string& name = s.right.nodes[v].name;
    for (const auto& x : s.right.nodes[v].expressions) {
      if (x.code.empty() && !x.unsupported.empty()) {
        add("E-unsupported", Severity::Warning, {name},
            "the Jerboa expression for '" + x.embedding + "' is not translated (" + x.unsupported +
                "): " + x.jerboa);
        continue;
      }
      size_t e = 0;
      while (e < sigs.size() && sigs[e].name != x.embedding) ++e;
      if (e == sigs.size()) {
        if (!s.find_embedding(x.embedding))
          add("E-undeclared", Severity::Error, {name},
              "expression for the undeclared embedding '" + x.embedding + "'");
        continue;
      }
      if (written[e][v]) {
        add("E-unique", Severity::Error, {name},
            "two expressions for embedding '" + x.embedding +
                "' on one node (thesis Def. 71, uniqueness)");
        continue;
      }
      written[e][v] = true;
      try {
        compiled[e][v] = expr::compile_expression(x.code, sigs[e], ctx, "");
      } catch (const Error& err) {
        add("E-expression", Severity::Error, {name},
            "embedding '" + x.embedding + "', " + err.location() + ": " + err.message());
      }
    }
  }
  for (size_t e = 0; e < sigs.size(); ++e) {
    const DimMask mask = sigs[e].orbit.mask();
    const auto rc = classes(s.right, mask);
    const auto lc = classes(s.left, mask);
    std::map<uint32_t, std::vector<uint32_t>> members;
    for (uint32_t v = 0; v < s.right.size(); ++v) members[rc[v]].push_back(v);
    for (const auto& [root, nodes] : members) {
      std::vector<std::string> names;
      for (uint32_t v : nodes) names.push_back(s.right.nodes[v].name);
      std::vector<uint32_t> with;
      bool malformed = false;
      for (uint32_t v : nodes) {
        if (compiled[e][v])
          with.push_back(v);
        else if (written[e][v])
          malformed = true;
      }
      if (malformed) continue;  // already reported
      if (!with.empty()) {
        const std::string first = expr::to_text(*compiled[e][with[0]]);
        for (uint32_t v : with)
          if (expr::to_text(*compiled[e][v]) != first) {
            add("E-orbit-terms", Severity::Error, names,
                "nodes " + s.right.nodes[with[0]].name + " and " + s.right.nodes[v].name +
                    " are in one " + sigs[e].orbit.str() + "-class of R and give '" + sigs[e].name +
                    "' different expressions: " + first + " and " + expr::to_text(*compiled[e][v]) +
                    " (thesis Def. 71, orbit consistency)");
            break;
          }
        continue;
      }
      std::set<uint32_t> origins;
      std::vector<uint32_t> preserved;
      for (uint32_t v : nodes)
        if (auto l = s.left_of(v)) {
          origins.insert(lc[*l]);
          preserved.push_back(v);
        }
      if (preserved.empty()) {
        add("E-no-value", Severity::Error, names,
            "a " + sigs[e].orbit.str() +
                "-class of added nodes without expression: its orbits get no '" + sigs[e].name +
                "' value (thesis Def. 81)");
        continue;
      }
      if (origins.size() > 1) {
        add("E-merge", Severity::Error, names,
            "the class joins preserved nodes of " + std::to_string(origins.size()) + " different " +
                sigs[e].orbit.str() +
                "-classes of L and has no expression: merged orbits may hold different '" +
                sigs[e].name + "' values");
        continue;
      }
      for (uint32_t v : preserved) {
        const OrbitType& rl = s.right.nodes[v].label;
        const OrbitType& ll = s.left.nodes[*s.left_of(v)].label;
        for (size_t p = 0; p < rl.size() && p < ll.size(); ++p) {
          const bool r_in = rl[p] != OrbitType::kHole && (mask >> rl[p] & 1u);
          const bool l_in = ll[p] != OrbitType::kHole && (mask >> ll[p] & 1u);
          if (r_in && !l_in) {
            add("E-merge-instances", Severity::Warning, {s.right.nodes[v].name},
                "label " + ll.str() + " -> " + rl.str() + " links, in " + sigs[e].orbit.str() +
                    ", instances of the node that L does not link: their '" + sigs[e].name +
                    "' values may differ and no expression sets them");
            break;
          }
        }
      }
    }
  }
  for (size_t k = before; k < out.size(); ++k)
    if (out[k].severity == Severity::Error) return false;
  return true;
}

}  // namespace gmr::checker
