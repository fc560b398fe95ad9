#include "checker/events/static_events.hpp"

#include <algorithm>
#include <optional>
#include <set>
#include <tuple>

#include "model/core/error.hpp"

namespace gmr::events {
using scheme::GraphScheme;
using scheme::RuleScheme;

const char* to_string(PatternEventKind k) {
  switch (k) {
    case PatternEventKind::Creation:
      return "creation";
    case PatternEventKind::Deletion:
      return "deletion";
    case PatternEventKind::ExplicitSplit:
      return "explicit split";
    case PatternEventKind::ImplicitSplit:
      return "implicit split";
    case PatternEventKind::ExplicitMerge:
      return "explicit merge";
    case PatternEventKind::ImplicitMerge:
      return "implicit merge";
    case PatternEventKind::Modification:
      return "modification";
    case PatternEventKind::NonModification:
      return "non-modification";
  }
  return "?";
}
bool is_split(PatternEventKind k) {
  return k == PatternEventKind::ExplicitSplit || k == PatternEventKind::ImplicitSplit;
}
bool is_merge(PatternEventKind k) {
  return k == PatternEventKind::ExplicitMerge || k == PatternEventKind::ImplicitMerge;
}
const char* to_string(Certainty c) { return c == Certainty::Certain ? "certain" : "possible"; }

std::vector<OrbitType> all_orbit_types(int n) {
  std::vector<OrbitType> out;
  const uint32_t count = 1u << (n + 1);
  for (int size = 0; size <= n + 1; ++size)
    for (uint32_t m = 0; m < count; ++m) {
      if (__builtin_popcount(m) != size) continue;
      std::vector<int> dims;
      for (int i = 0; i <= n; ++i)
        if (m >> i & 1u) dims.push_back(i);
      out.emplace_back(dims);
    }
  std::sort(out.begin(), out.end(), [](const OrbitType& a, const OrbitType& b) {
    if (a.size() != b.size()) return a.size() < b.size();
    return a.dims() < b.dims();
  });
  return out;
}

std::string pattern_orbit_name(const RuleScheme& s, const OrbitTypeEvents& t, Side side,
                               uint32_t c) {
  const PatternOrbits& p = side == Side::L ? t.left : t.right;
  const GraphScheme& g = side == Side::L ? s.left : s.right;
  return std::string(to_string(side)) + t.orbit.str() + "(" + g.nodes[p.nodes[c].front()].name +
         ")";
}

namespace {

bool in(DimMask o, int d) { return d >= 0 && (o >> d & 1u); }

int label_at(const GraphScheme& g, uint32_t m, size_t k) {
  const auto& dims = g.nodes[m].label.dims();
  return k < dims.size() ? dims[k] : OrbitType::kHole;
}

// The explicit <o>-arcs of the given nodes of one side, as (name, name, dim) with names ordered.
std::multiset<std::tuple<std::string, std::string, int>> arcs_in(
    const GraphScheme& g, DimMask o, const std::vector<uint32_t>& nodes) {
  std::multiset<std::tuple<std::string, std::string, int>> out;
  for (const auto& e : g.arcs) {
    if (!in(o, e.dim)) continue;
    if (!std::binary_search(nodes.begin(), nodes.end(), e.a)) continue;
    std::string a = g.nodes[e.a].name, b = g.nodes[e.b].name;
    if (b < a) std::swap(a, b);
    out.emplace(a, b, e.dim);
  }
  return out;
}

class Analysis {
 public:
  Analysis(const RuleScheme& s, const OrbitType& o) : s_(s), o_(o.mask()) {
    t_.orbit = o;
    t_.left = pattern_orbits(s.left, Side::L, o_);
    t_.right = pattern_orbits(s.right, Side::R, o_);
    arity_ = s.orbit.size();
  }

  OrbitTypeEvents run() {
    creations_and_deletions();
    std::vector<bool> flagged(t_.left.size(), false);
    splits(flagged);
    merges(flagged);
    residuals(flagged);
    return std::move(t_);
  }

 private:
  uint32_t lclass(uint32_t m) const { return t_.left.class_of[m]; }
  uint32_t rclass(uint32_t m) const { return t_.right.class_of[m]; }

  // Def. 3.1.1 and Def. 3.4.1: certain (created and deleted pattern orbits are complete).
  void creations_and_deletions() {
    for (uint32_t c = 0; c < t_.right.size(); ++c) {
      bool created = true;
      for (uint32_t m : t_.right.nodes[c]) created = created && !s_.left_of(m);
      if (created)
        t_.events.push_back({PatternEventKind::Creation, Certainty::Certain, {}, {c}, {}, {}});
    }
    for (uint32_t c = 0; c < t_.left.size(); ++c) {
      bool deleted = true;
      for (uint32_t m : t_.left.nodes[c]) deleted = deleted && !s_.right_of(m);
      if (deleted)
        t_.events.push_back({PatternEventKind::Deletion, Certainty::Certain, {c}, {}, {}, {}});
    }
  }

  // Positions k with: some node of `from` (side X) has λ^X_k in <o>, no node of `to` (side Y) has.
  std::vector<uint32_t> lost_positions(const GraphScheme& x, const std::vector<uint32_t>& from,
                                       const GraphScheme& y,
                                       const std::vector<uint32_t>& to) const {
    std::vector<uint32_t> out;
    for (uint32_t k = 0; k < arity_; ++k) {
      bool before = false, after = false;
      for (uint32_t m : from) before = before || in(o_, label_at(x, m, k));
      for (uint32_t m : to) after = after || in(o_, label_at(y, m, k));
      if (before && !after) out.push_back(k);
    }
    return out;
  }

  // Def. 3.2.1 (a) and (b), per pair (L pattern orbit, R pattern orbit).
  void splits(std::vector<bool>& flagged) {
    for (uint32_t c = 0; c < t_.left.size(); ++c) {
      std::vector<uint32_t> rs;     // R pattern orbits of the preserved nodes, first seen order
      std::vector<uint32_t> first;  // a preserved L node landing in each
      for (uint32_t m : t_.left.nodes[c]) {
        const auto r = s_.right_of(m);
        if (!r) continue;
        const uint32_t d = rclass(*r);
        if (std::find(rs.begin(), rs.end(), d) == rs.end()) {
          rs.push_back(d);
          first.push_back(m);
        }
      }
      if (rs.empty()) continue;
      if (rs.size() > 1) {
        PatternEvent e{PatternEventKind::ExplicitSplit, Certainty::Possible, {c}, rs, {}, {}};
        for (uint32_t d : rs)
          if (t_.right.complete[d]) e.certainty = Certainty::Certain;
        for (size_t i = 0; i < first.size(); ++i)
          for (size_t j = i + 1; j < first.size(); ++j) e.pairs.push_back({first[i], first[j], -1});
        t_.events.push_back(std::move(e));
        flagged[c] = true;
      }
      for (size_t i = 0; i < rs.size(); ++i) {
        auto ks = lost_positions(s_.left, t_.left.nodes[c], s_.right, t_.right.nodes[rs[i]]);
        if (ks.empty()) continue;
        PatternEvent e{PatternEventKind::ImplicitSplit, Certainty::Possible, {c}, {rs[i]}, ks, {}};
        for (uint32_t k : ks) e.pairs.push_back({first[i], first[i], static_cast<int>(k)});
        t_.events.push_back(std::move(e));
        flagged[c] = true;
      }
    }
  }

  // Def. 3.3.1 (a) and (b): as splits with the sides exchanged; pairs name L nodes.
  void merges(std::vector<bool>& flagged) {
    for (uint32_t d = 0; d < t_.right.size(); ++d) {
      std::vector<uint32_t> ls;
      std::vector<uint32_t> first;  // L node of a preserved node of d in each L pattern orbit
      for (uint32_t m : t_.right.nodes[d]) {
        const auto l = s_.left_of(m);
        if (!l) continue;
        const uint32_t c = lclass(*l);
        if (std::find(ls.begin(), ls.end(), c) == ls.end()) {
          ls.push_back(c);
          first.push_back(*l);
        }
      }
      if (ls.empty()) continue;
      if (ls.size() > 1) {
        PatternEvent e{PatternEventKind::ExplicitMerge, Certainty::Possible, ls, {d}, {}, {}};
        for (uint32_t c : ls)
          if (t_.left.complete[c]) e.certainty = Certainty::Certain;
        for (size_t i = 0; i < first.size(); ++i)
          for (size_t j = i + 1; j < first.size(); ++j) e.pairs.push_back({first[i], first[j], -1});
        t_.events.push_back(std::move(e));
        for (uint32_t c : ls) flagged[c] = true;
      }
      for (size_t i = 0; i < ls.size(); ++i) {
        auto ks = lost_positions(s_.right, t_.right.nodes[d], s_.left, t_.left.nodes[ls[i]]);
        if (ks.empty()) continue;
        PatternEvent e{PatternEventKind::ImplicitMerge, Certainty::Possible, {ls[i]}, {d}, ks, {}};
        for (uint32_t k : ks) e.pairs.push_back({first[i], first[i], static_cast<int>(k)});
        t_.events.push_back(std::move(e));
        flagged[ls[i]] = true;
      }
    }
  }

  // Def. 3.4.2 and §3.4.3 for the L pattern orbits with preserved nodes.
  void residuals(const std::vector<bool>& flagged) {
    t_.residual.assign(t_.left.size(), PatternEventKind::Modification);
    for (uint32_t c = 0; c < t_.left.size(); ++c) {
      const auto& cn = t_.left.nodes[c];
      std::optional<uint32_t> d;
      for (uint32_t m : cn)
        if (auto r = s_.right_of(m)) {
          d = rclass(*r);
          break;
        }
      if (!d) continue;
      t_.residual[c] = unchanged(cn, t_.right.nodes[*d]) ? PatternEventKind::NonModification
                                                         : PatternEventKind::Modification;
      if (!flagged[c]) t_.events.push_back({t_.residual[c], Certainty::Certain, {c}, {*d}, {}, {}});
    }
  }

  bool unchanged(const std::vector<uint32_t>& cn, const std::vector<uint32_t>& dn) const {
    if (cn.size() != dn.size()) return false;
    std::vector<uint32_t> mapped;
    for (uint32_t m : dn) {
      const auto l = s_.left_of(m);
      if (!l) return false;
      mapped.push_back(*l);
    }
    std::sort(mapped.begin(), mapped.end());
    if (mapped != cn) return false;
    if (arcs_in(s_.left, o_, cn) != arcs_in(s_.right, o_, dn)) return false;
    for (uint32_t m : cn) {
      const uint32_t r = *s_.right_of(m);
      for (uint32_t k = 0; k < arity_; ++k) {
        const int a = label_at(s_.left, m, k), b = label_at(s_.right, r, k);
        if ((in(o_, a) || in(o_, b)) && a != b) return false;
      }
    }
    return true;
  }

  const RuleScheme& s_;
  DimMask o_;
  size_t arity_ = 0;
  OrbitTypeEvents t_;
};

}  // namespace

StaticEvents analyse(const RuleScheme& s, const std::vector<OrbitType>& types) {
  s.validate_structure();
  StaticEvents out;
  out.rule = s.name;
  out.dimension = s.dimension;
  for (uint32_t v = 0; v < s.left.size(); ++v)
    out.right_of.push_back(s.right_of(v).value_or(StaticEvents::kDeletedNode));
  const std::vector<OrbitType> ts = types.empty() ? all_orbit_types(s.dimension) : types;
  for (const OrbitType& o : ts) {
    if (o.has_hole()) throw Error(ErrorCode::Range, "an analysed orbit type has no `_`", o.str());
    for (int d : o.dims())
      if (d < 0 || d > s.dimension)
        throw Error(ErrorCode::Range,
                    "dimension " + std::to_string(d) + " is not a dimension of the scheme (n = " +
                        std::to_string(s.dimension) + ")",
                    o.str());
    out.orbits.push_back(Analysis(s, o).run());
  }
  return out;
}

}  // namespace gmr::events
