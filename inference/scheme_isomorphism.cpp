#include "inference/scheme_isomorphism.hpp"

#include <algorithm>
#include <deque>
#include <map>
#include <numeric>
#include <string_view>
#include <unordered_map>

#include "model/core/error.hpp"

namespace gmr::inference {

using namespace gmr::scheme;

namespace {

constexpr uint32_t kNone = UINT32_MAX;

// The joint representation κ(L,R) of a scheme as a node-labelled graph.
struct Joint {
  size_t slots = 0;  // n+2: 0..n, then κ
  size_t left = 0;   // nodes 0..left-1 are L, the rest R
  std::vector<std::vector<int>> label;
  std::vector<uint32_t> nbr;  // nbr[v * slots + slot]

  size_t size() const { return label.size(); }
  uint32_t at(uint32_t v, size_t slot) const { return nbr[v * slots + slot]; }

  std::vector<int> signature(uint32_t v) const {
    std::vector<int> sig{v < left ? 0 : 1};
    sig.insert(sig.end(), label[v].begin(), label[v].end());
    for (size_t i = 0; i < slots; ++i) {
      const uint32_t x = at(v, i);
      sig.push_back(x == kNone ? 0 : x == v ? 2 : 1);
    }
    return sig;
  }
};

Joint joint_of(const RuleScheme& s, const std::vector<size_t>& perm) {
  Joint j;
  j.slots = static_cast<size_t>(s.dimension) + 2;
  j.left = s.left.size();
  const size_t total = s.left.size() + s.right.size();
  j.nbr.assign(total * j.slots, kNone);
  auto add_side = [&](const GraphScheme& g, uint32_t base, const char* side) {
    for (const auto& n : g.nodes) {
      std::vector<int> l(perm.size());
      for (size_t q = 0; q < perm.size(); ++q) l[q] = n.label[perm[q]];
      j.label.push_back(std::move(l));
    }
    for (const auto& e : g.arcs) {
      if (e.dim < 0 || e.dim > s.dimension)
        throw Error(ErrorCode::Usage,
                    std::string("arc of dimension ") + std::to_string(e.dim) + " in " + side);
      for (auto [u, w] : {std::pair{e.a, e.b}, std::pair{e.b, e.a}}) {
        uint32_t& slot = j.nbr[(base + u) * j.slots + static_cast<size_t>(e.dim)];
        if (slot != kNone && slot != base + w)
          throw Error(ErrorCode::Usage, std::string("node ") + g.nodes[u].name + " of " + side +
                                            " has two " + std::to_string(e.dim) +
                                            "-arcs: no joint representation (Def. 90)");
        slot = base + w;
      }
    }
  };
  add_side(s.left, 0, "L");
  add_side(s.right, static_cast<uint32_t>(s.left.size()), "R");
  // κ arcs: preserved nodes by name (RuleScheme::right_of, through an index: linear in the scheme).
  std::unordered_map<std::string_view, uint32_t> right_index;
  for (uint32_t v = 0; v < s.right.size(); ++v) right_index.emplace(s.right.nodes[v].name, v);
  for (uint32_t v = 0; v < s.left.size(); ++v)
    if (auto r = right_index.find(s.left.nodes[v].name); r != right_index.end()) {
      const auto w = static_cast<uint32_t>(s.left.size() + r->second);
      j.nbr[v * j.slots + j.slots - 1] = w;
      j.nbr[w * j.slots + j.slots - 1] = v;
    }
  return j;
}

struct Matcher {
  const Joint& a;
  const Joint& b;
  std::vector<std::vector<int>> sa, sb;
  std::vector<uint32_t> mapd, mapr;

  // Joint BFS from v -> w (Alg. 7 inner loop). On failure, undoes its own assignments.
  bool grow(uint32_t v, uint32_t w) {
    std::vector<uint32_t> added{v};
    mapd[v] = w;
    mapr[w] = v;
    std::deque<uint32_t> q{v};
    bool ok = true;
    while (!q.empty() && ok) {
      const uint32_t u = q.front();
      q.pop_front();
      const uint32_t u2 = mapd[u];
      for (size_t i = 0; i < a.slots && ok; ++i) {
        const uint32_t x = a.at(u, i);
        if (x == kNone || x == u) continue;  // δ_i = 0 or 2: already compared in the signatures
        const uint32_t x2 = b.at(u2, i);
        if (x2 == kNone || sa[x] != sb[x2] || (mapd[x] != kNone && mapd[x] != x2) ||
            (mapr[x2] != kNone && mapr[x2] != x)) {
          ok = false;
          break;
        }
        if (mapd[x] == kNone) {
          mapd[x] = x2;
          mapr[x2] = x;
          added.push_back(x);
          q.push_back(x);
        }
      }
    }
    if (!ok)
      for (uint32_t x : added) {
        mapr[mapd[x]] = kNone;
        mapd[x] = kNone;
      }
    return ok;
  }

  // Matches the components of a in order (roots[k]), with backtracking.
  bool match(const std::vector<uint32_t>& roots, size_t k) {
    if (k == roots.size()) return true;
    const uint32_t v = roots[k];
    if (mapd[v] != kNone) return match(roots, k + 1);
    for (uint32_t w = 0; w < b.size(); ++w) {
      if (mapr[w] != kNone || sb[w] != sa[v]) continue;
      std::vector<uint32_t> before = mapd;
      if (!grow(v, w)) continue;
      if (match(roots, k + 1)) return true;
      // Undo this component.
      for (uint32_t x = 0; x < a.size(); ++x)
        if (before[x] == kNone && mapd[x] != kNone) {
          mapr[mapd[x]] = kNone;
          mapd[x] = kNone;
        }
    }
    return false;
  }
};

std::optional<SchemeIsomorphism> try_permutation(const RuleScheme& s1, const RuleScheme& s2,
                                                 const std::vector<size_t>& perm) {
  std::vector<size_t> id(perm.size());
  std::iota(id.begin(), id.end(), size_t{0});
  const Joint a = joint_of(s1, perm), b = joint_of(s2, id);
  Matcher m{
      a, b, {}, {}, std::vector<uint32_t>(a.size(), kNone), std::vector<uint32_t>(b.size(), kNone)};
  std::map<std::vector<int>, size_t> hist;
  for (uint32_t v = 0; v < a.size(); ++v) {
    m.sa.push_back(a.signature(v));
    ++hist[m.sa.back()];
  }
  for (uint32_t v = 0; v < b.size(); ++v) {
    m.sb.push_back(b.signature(v));
    auto it = hist.find(m.sb.back());
    if (it == hist.end() || it->second == 0) return std::nullopt;  // compareSig
    --it->second;
  }
  // Roots: per component of a, the node of the rarest signature (minSig), first in index order.
  std::vector<uint32_t> comp(a.size(), kNone), roots;
  std::map<std::vector<int>, size_t> count;
  for (const auto& s : m.sa) ++count[s];
  for (uint32_t v = 0; v < a.size(); ++v) {
    if (comp[v] != kNone) continue;
    const auto c = static_cast<uint32_t>(roots.size());
    uint32_t best = v;
    std::vector<uint32_t> stack{v};
    comp[v] = c;
    while (!stack.empty()) {
      const uint32_t u = stack.back();
      stack.pop_back();
      if (count[m.sa[u]] < count[m.sa[best]]) best = u;
      for (size_t i = 0; i < a.slots; ++i) {
        const uint32_t x = a.at(u, i);
        if (x != kNone && comp[x] == kNone) {
          comp[x] = c;
          stack.push_back(x);
        }
      }
    }
    roots.push_back(best);
  }
  if (!m.match(roots, 0)) return std::nullopt;
  SchemeIsomorphism iso;
  iso.positions = perm;
  const auto nl = static_cast<uint32_t>(a.left);
  for (uint32_t v = 0; v < a.size(); ++v) {
    if (m.mapd[v] == kNone)
      return std::nullopt;  // full cover (Alg. 7 as printed returns mapd unchecked)
    if (v < nl)
      iso.left.push_back(m.mapd[v]);
    else
      iso.right.push_back(m.mapd[v] - nl);
  }
  return iso;
}

}  // namespace

std::optional<SchemeIsomorphism> scheme_isomorphism(const RuleScheme& a, const RuleScheme& b,
                                                    const SchemeIsomorphismOptions& opt) {
  if (a.dimension != b.dimension || a.orbit.size() != b.orbit.size() ||
      a.left.size() != b.left.size() || a.right.size() != b.right.size())
    return std::nullopt;
  for (const GraphScheme* g : {&a.left, &a.right, &b.left, &b.right})
    for (const auto& n : g->nodes)
      if (n.label.size() != a.orbit.size())
        throw Error(ErrorCode::Usage, "node " + n.name + " has a label of the wrong arity");
  std::vector<size_t> perm(a.orbit.size());
  std::iota(perm.begin(), perm.end(), size_t{0});
  do {
    if (auto iso = try_permutation(a, b, perm)) return iso;
  } while (!opt.exact_positions && std::next_permutation(perm.begin(), perm.end()));
  return std::nullopt;
}

}  // namespace gmr::inference
