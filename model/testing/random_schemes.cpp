#include "model/testing/random_schemes.hpp"

#include <algorithm>

#include "model/core/error.hpp"

namespace gmr::testing {
using namespace gmr::scheme;

namespace {

size_t pick(Rng& rng, size_t k) { return static_cast<size_t>(uniform(rng, 0, k - 1)); }

// A positional relabeling of <o> (Def. 86): position p gets a distinct dimension of 0..n or `_`.
OrbitType random_relabeling(Rng& rng, const OrbitType& o, int n) {
  std::vector<Dart> perm = random_permutation(rng, static_cast<size_t>(n + 1));
  std::vector<int> dims;
  for (size_t p = 0; p < o.size(); ++p) {
    if (chance(rng, 30))
      dims.push_back(OrbitType::kHole);
    else if (chance(rng, 50))
      dims.push_back(o[p]);  // often the identity at this position
    else
      dims.push_back(static_cast<int>(perm[p]));
  }
  // Make the non-hole dimensions distinct (injective relabeling): later duplicates become `_`.
  std::vector<bool> used(static_cast<size_t>(n + 1), false);
  for (int& d : dims) {
    if (d == OrbitType::kHole) continue;
    if (used[static_cast<size_t>(d)])
      d = OrbitType::kHole;
    else
      used[static_cast<size_t>(d)] = true;
  }
  return OrbitType(std::move(dims));
}

bool has_dim(const GraphScheme& g, uint32_t v, int d) { return g.count_arcs(v, d) > 0; }

}  // namespace

RuleScheme random_scheme(Rng& rng, const RandomSchemeOptions& opt) {
  const int n = opt.n;
  if (n < 0 || n >= kMaxDim) throw Error(ErrorCode::Range, "random_scheme: bad dimension");
  RuleScheme s;
  s.name = "random";
  s.dimension = n;
  // <o>: a random non-empty subset of 0..n.
  std::vector<int> o;
  while (o.empty())
    for (int i = 0; i <= n; ++i)
      if (chance(rng, 55)) o.push_back(i);
  s.orbit = OrbitType(o);
  s.left.add_node("n0", s.orbit);
  s.hooks = {"n0"};
  // Optional second L node, joined by an explicit arc of a dimension outside <o>.
  std::vector<int> outside;
  for (int i = 0; i <= n; ++i)
    if (!s.orbit.contains(i)) outside.push_back(i);
  if (!outside.empty() && chance(rng, opt.second_left_percent)) {
    OrbitType lab = random_relabeling(rng, s.orbit, n);
    const int d = outside[pick(rng, outside.size())];
    std::vector<int> dims = lab.dims();
    for (int& x : dims)
      if (x == d) x = OrbitType::kHole;
    s.left.add_node("n1", OrbitType(dims));
    s.left.add_arc("n0", "n1", d);
  }
  // R: each L node preserved with probability 85% (the hook at least once in three), added nodes.
  for (const SchemeNode& v : s.left.nodes)
    if (chance(rng, 85))
      s.right.add_node(v.name, chance(rng, 40) ? v.label : random_relabeling(rng, s.orbit, n));
  const size_t added = pick(rng, opt.max_added + 1);
  for (size_t k = 0; k < added; ++k)
    s.right.add_node("a" + std::to_string(k), random_relabeling(rng, s.orbit, n));
  // Keep explicit L arcs between preserved nodes most of the time.
  for (const SchemeArc& e : s.left.arcs) {
    const auto ra = s.right_of(e.a), rb = s.right_of(e.b);
    if (ra && rb && chance(rng, 80) && !has_dim(s.right, *ra, e.dim) &&
        !has_dim(s.right, *rb, e.dim))
      s.right.arcs.push_back({*ra, *rb, e.dim});
  }
  // Incident arcs (Alg. 1): a preserved node should have in R exactly the dimensions it has in L
  // (the others keep their outside links), an added node every dimension. Most of the time, clear
  // the label positions that give a preserved node an extra dimension, and complete the missing
  // dimensions by explicit arcs (to a node also missing it) or loops.
  const uint32_t m = static_cast<uint32_t>(s.right.size());
  auto wanted = [&](uint32_t v, int d) {
    const auto l = s.left_of(v);
    return !l || has_dim(s.left, *l, d);
  };
  for (uint32_t v = 0; v < m; ++v) {
    std::vector<int> dims = s.right.nodes[v].label.dims();
    for (int& x : dims)
      if (x != OrbitType::kHole && !wanted(v, x) && chance(rng, opt.complete_percent))
        x = OrbitType::kHole;
    s.right.nodes[v].label = OrbitType(dims);
  }
  for (int d = 0; d <= n; ++d) {
    for (uint32_t v = 0; v < m; ++v) {
      if (has_dim(s.right, v, d) || !wanted(v, d) || !chance(rng, opt.complete_percent)) continue;
      std::vector<uint32_t> partners;
      for (uint32_t w = 0; w < m; ++w)
        if (w != v && !has_dim(s.right, w, d) && wanted(w, d)) partners.push_back(w);
      if (!partners.empty() && chance(rng, 70))
        s.right.arcs.push_back({v, partners[pick(rng, partners.size())], d});
      else
        s.right.arcs.push_back({v, v, d});
    }
  }
  return s;
}

RuleScheme random_copies_scheme(Rng& rng, int n, size_t max_nodes) {
  RuleScheme s;
  s.name = "copies";
  s.dimension = n;
  s.orbit = OrbitType::range(0, n);
  std::vector<int> rev;
  for (int i = n; i >= 0; --i) rev.push_back(i);
  s.left.add_node("n0", s.orbit);
  s.hooks = {"n0"};
  const size_t count = static_cast<size_t>(uniform(rng, 1, std::max<size_t>(max_nodes, 1)));
  const bool keep_hook = chance(rng, 70);
  for (size_t k = 0; k < count; ++k) {
    const std::string name = k == 0 && keep_hook ? "n0" : "c" + std::to_string(k);
    s.right.add_node(name, chance(rng, 50) ? s.orbit : OrbitType(rev));
  }
  return s;
}

std::string mutate_scheme(Rng& rng, RuleScheme& s) {
  const int n = s.dimension;
  for (int attempt = 0; attempt < 16; ++attempt) {
    switch (pick(rng, 5)) {
      case 0: {  // change one position of an R label
        if (s.right.nodes.empty() || s.orbit.size() == 0) break;
        const size_t v = pick(rng, s.right.size());
        std::vector<int> dims = s.right.nodes[v].label.dims();
        const size_t p = pick(rng, dims.size());
        const int nd = chance(rng, 50)
                           ? OrbitType::kHole
                           : static_cast<int>(uniform(rng, 0, static_cast<uint64_t>(n)));
        if (dims[p] == nd || (nd != OrbitType::kHole && std::count(dims.begin(), dims.end(), nd)))
          break;
        dims[p] = nd;
        s.right.nodes[v].label = OrbitType(dims);
        return "relabel R " + s.right.nodes[v].name + " position " + std::to_string(p);
      }
      case 1: {  // add an explicit R arc
        if (s.right.nodes.empty()) break;
        const auto a = static_cast<uint32_t>(pick(rng, s.right.size()));
        const auto b = static_cast<uint32_t>(pick(rng, s.right.size()));
        const int d = static_cast<int>(uniform(rng, 0, static_cast<uint64_t>(n)));
        s.right.arcs.push_back({a, b, d});
        return "add R arc " + s.right.nodes[a].name + " -" + std::to_string(d) + "- " +
               s.right.nodes[b].name;
      }
      case 2: {  // remove an explicit R arc
        if (s.right.arcs.empty()) break;
        const size_t k = pick(rng, s.right.arcs.size());
        s.right.arcs.erase(s.right.arcs.begin() + static_cast<long>(k));
        return "remove R arc " + std::to_string(k);
      }
      case 3:  // drop an R node (an added node disappears; a preserved one becomes deleted)
      case 4: {
        if (s.right.nodes.empty()) break;
        const auto v = static_cast<uint32_t>(pick(rng, s.right.size()));
        const std::string name = s.right.nodes[v].name;
        GraphScheme r;
        std::vector<uint32_t> pos(s.right.size(), UINT32_MAX);
        for (uint32_t w = 0; w < s.right.size(); ++w)
          if (w != v) pos[w] = r.add_node(s.right.nodes[w].name, s.right.nodes[w].label);
        for (const SchemeArc& e : s.right.arcs)
          if (e.a != v && e.b != v) r.arcs.push_back({pos[e.a], pos[e.b], e.dim});
        s.right = std::move(r);
        return "drop R node " + name;
      }
    }
  }
  return "none";
}

}  // namespace gmr::testing
