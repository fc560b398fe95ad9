#include "checker/events/event_log.hpp"

#include <algorithm>
#include <map>
#include <numeric>
#include <set>
#include <unordered_map>

#include "model/core/error.hpp"
#include "model/core/orbit.hpp"

namespace gmr::events {
using scheme::GraphScheme;
using scheme::OrbitGraph;
using scheme::RuleScheme;
using scheme::SchemeApplication;

namespace {

uint32_t find(std::vector<uint32_t>& parent, uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

// Names (lowest darts) of the instances of one side's pattern orbits: names[v * s + b] for node v
// and orbit index b, `table` being the match (L, on G) or the comatch (R, on H).
class InstanceNamer {
 public:
  InstanceNamer(const GMap& g, const OrbitGraph& O, const std::vector<Dart>& table, size_t nodes)
      : g_(g), O_(O), table_(table), nodes_(nodes), s_(O.size()) {}

  std::vector<Dart> names(const PatternOrbits& p, size_t& traversed) {
    std::vector<Dart> out(nodes_ * s_, kNoDart);
    for (uint32_t c = 0; c < p.size(); ++c) {
      if (p.complete[c]) name_complete(p, c, out);
      else name_by_traversal(p, c, out, traversed);
    }
    return out;
  }

 private:
  // A complete pattern orbit: its instance components (the sub-orbits of the hook orbit along its
  // positions) are whole orbits of the map.
  void name_complete(const PatternOrbits& p, uint32_t c, std::vector<Dart>& out) const {
    std::vector<uint32_t> parent(s_);
    std::iota(parent.begin(), parent.end(), 0u);
    for (uint32_t k : p.positions[c])
      for (uint32_t b = 0; b < s_; ++b) parent[find(parent, b)] = find(parent, O_.neighbor(b, k));
    std::vector<Dart> low(s_, kNoDart);
    for (uint32_t m : p.nodes[c])
      for (uint32_t b = 0; b < s_; ++b) {
        Dart& l = low[find(parent, b)];
        l = std::min(l, table_[m * s_ + b]);
      }
    for (uint32_t m : p.nodes[c])
      for (uint32_t b = 0; b < s_; ++b) out[m * s_ + b] = low[find(parent, b)];
  }

  void name_by_traversal(const PatternOrbits& p, uint32_t c, std::vector<Dart>& out, size_t& traversed) {
    if (slot_.empty())
      for (uint32_t k = 0; k < table_.size(); ++k) slot_.emplace(table_[k], k);
    ScopedMarker seen(g_);
    std::vector<Dart> stack, visited;
    for (uint32_t m : p.nodes[c])
      for (uint32_t b = 0; b < s_; ++b) {
        if (out[m * s_ + b] != kNoDart) continue;
        visited.clear();
        visit_orbit_marked(g_, p.orbit, table_[m * s_ + b], seen.id(), stack,
                           [&](Dart x) { visited.push_back(x); });
        const Dart low = *std::min_element(visited.begin(), visited.end());
        for (Dart x : visited) {
          seen.unmark(x);
          auto it = slot_.find(x);
          if (it != slot_.end()) out[it->second] = low;
        }
        traversed += visited.size();
      }
    seen.set_clean();
  }

  const GMap& g_;
  const OrbitGraph& O_;
  const std::vector<Dart>& table_;
  size_t nodes_, s_;
  std::unordered_map<Dart, uint32_t> slot_;
};

class Recorder {
 public:
  Recorder(const RuleScheme& s, const StaticEvents& st) : s_(s), st_(st) {}

  // Step 1 (G before the rewrite).
  void before(const GMap& g, const OrbitGraph& O, const SchemeApplication& res) {
    O_ = O;
    ns_ = O.size();
    M_ = res.match;
    dims_ = g.dimension() + 1;
    old_.resize(M_.size() * dims_);
    for (size_t k = 0; k < M_.size(); ++k)
      for (int i = 0; i < dims_; ++i) old_[k * dims_ + i] = g.alpha(i, M_[k]);
    InstanceNamer namer(g, O_, M_, s_.left.size());
    logs_.resize(st_.orbits.size());
    gname_.resize(st_.orbits.size());
    for (size_t t = 0; t < st_.orbits.size(); ++t) {
      logs_[t].orbit = st_.orbits[t].orbit;
      gname_[t] = namer.names(st_.orbits[t].left, logs_[t].traversed);
    }
  }

  // Steps 3 and 4 (H after the rewrite).
  std::vector<OrbitTypeLog> after(const GMap& h, const SchemeApplication& res) {
    InstanceNamer namer(h, O_, res.comatch, s_.right.size());
    for (size_t t = 0; t < st_.orbits.size(); ++t) {
      const std::vector<Dart> hname = namer.names(st_.orbits[t].right, logs_[t].traversed);
      log_orbit_type(h, st_.orbits[t], gname_[t], hname, logs_[t]);
    }
    return std::move(logs_);
  }

 private:
  Dart l_slot(uint32_t v, uint32_t b) const { return v * static_cast<uint32_t>(ns_) + b; }

  void log_orbit_type(const GMap& h, const OrbitTypeEvents& te, const std::vector<Dart>& gname,
                      const std::vector<Dart>& hname, OrbitTypeLog& log) const {
    const OrbitType& o = te.orbit;
    std::map<Dart, EventStatus> split, merge;  // G-orbits split, H-orbits merged
    std::set<uint32_t> flagged;                // L pattern orbits with a split or merge flag
    for (uint32_t ei = 0; ei < te.events.size(); ++ei) {
      const PatternEvent& e = te.events[ei];
      if (e.kind == PatternEventKind::Deletion || e.kind == PatternEventKind::Creation) {
        const bool del = e.kind == PatternEventKind::Deletion;
        const auto& nodes = del ? te.left.nodes[e.left[0]] : te.right.nodes[e.right[0]];
        std::set<Dart> names;
        for (uint32_t m : nodes)
          for (uint32_t b = 0; b < ns_; ++b) names.insert(del ? gname[l_slot(m, b)] : hname[l_slot(m, b)]);
        for (Dart n : names)
          log.events.push_back({del ? OrbitEventKind::Deletion : OrbitEventKind::Creation, o,
                                del ? std::vector<Dart>{n} : std::vector<Dart>{},
                                del ? std::vector<Dart>{} : std::vector<Dart>{n}, EventStatus::Certain});
        continue;
      }
      const bool sp = is_split(e.kind), mg = is_merge(e.kind);
      if (!sp && !mg) continue;
      for (uint32_t c : e.left) flagged.insert(c);
      for (const InstancePair& p : e.pairs)
        for (uint32_t b = 0; b < ns_; ++b) {
          const uint32_t b2 = p.position < 0 ? b : O_.neighbor(b, static_cast<size_t>(p.position));
          const uint32_t ra = sp ? *s_.right_of(p.a) : 0, rb = sp ? *s_.right_of(p.b) : 0;
          const Dart na = sp ? hname[l_slot(ra, b)] : gname[l_slot(p.a, b)];
          const Dart nb = sp ? hname[l_slot(rb, b2)] : gname[l_slot(p.b, b2)];
          const bool different = na != nb;
          if (e.certainty == Certainty::Possible)
            log.checks.push_back({ei, sp ? 'H' : 'G', M_[l_slot(p.a, b)], M_[l_slot(p.b, b2)], different});
          if (!different) continue;
          auto& into = sp ? split : merge;
          const Dart at = sp ? gname[l_slot(p.a, b)] : hname[l_slot(*s_.right_of(p.a), b)];
          const EventStatus st =
              e.certainty == Certainty::Certain ? EventStatus::Certain : EventStatus::Confirmed;
          auto [it, fresh] = into.emplace(at, st);
          if (!fresh && st == EventStatus::Certain) it->second = st;
        }
    }
    // The (G-orbit, H-orbit) pairs of the preserved matched darts, and the matched darts' fate.
    std::map<Dart, std::set<Dart>> outs, ins;
    std::map<Dart, bool> changed, touches_flag;
    for (uint32_t v = 0; v < s_.left.size(); ++v) {
      const auto r = s_.right_of(v);
      const uint32_t c = te.left.class_of[v];
      for (uint32_t b = 0; b < ns_; ++b) {
        const Dart gn = gname[l_slot(v, b)];
        bool& ch = changed[gn];
        if (flagged.count(c)) touches_flag[gn] = true;
        if (!r) {
          ch = true;
          continue;
        }
        const Dart hn = hname[l_slot(*r, b)];
        outs[gn].insert(hn);
        ins[hn].insert(gn);
        const Dart d = M_[l_slot(v, b)];
        for (int i : o.dims())
          if (old_[l_slot(v, b) * dims_ + i] != h.alpha(i, d)) ch = true;
      }
    }
    for (auto [gn, st] : split)
      log.events.push_back({OrbitEventKind::Split, o, {gn}, {outs[gn].begin(), outs[gn].end()}, st});
    for (auto [hn, st] : merge)
      log.events.push_back({OrbitEventKind::Merge, o, {ins[hn].begin(), ins[hn].end()}, {hn}, st});
    for (const auto& [gn, hs] : outs) {
      if (split.count(gn)) continue;
      const Dart hn = *hs.begin();
      if (merge.count(hn)) continue;
      const EventStatus st = touches_flag.count(gn) ? EventStatus::Refuted : EventStatus::Certain;
      log.events.push_back({changed[gn] ? OrbitEventKind::Modification : OrbitEventKind::NonModification,
                            o, {gn}, {hn}, st});
    }
    sort_events(log.events);
  }

  const RuleScheme& s_;
  const StaticEvents& st_;
  OrbitGraph O_;
  size_t ns_ = 0;
  int dims_ = 0;
  std::vector<Dart> M_, old_;
  std::vector<OrbitTypeLog> logs_;
  std::vector<std::vector<Dart>> gname_;
};

}  // namespace

LoggedApplication apply_with_events(const scheme::SchemeEngine& engine, const StaticEvents& analysis,
                                    GMap& g, const std::vector<Dart>& hooks) {
  const RuleScheme& s = engine.scheme();
  if (analysis.rule != s.name || analysis.dimension != s.dimension)
    throw Error(ErrorCode::Usage, "the static events are those of rule \"" + analysis.rule + "\"",
                "scheme " + s.name);
  for (const auto& t : analysis.orbits)
    if (t.left.class_of.size() != s.left.size() || t.right.class_of.size() != s.right.size())
      throw Error(ErrorCode::Usage, "the static events do not match the scheme's nodes", "scheme " + s.name);
  LoggedApplication out;
  out.log.rule = s.name;
  out.log.hooks = hooks;
  Recorder rec(s, analysis);
  out.application = engine.apply(
      g, hooks, [&](const GMap& before, const OrbitGraph& O, const SchemeApplication& res) {
        rec.before(before, O, res);
      });
  if (out.application) out.log.orbits = rec.after(g, out.application);
  return out;
}

}  // namespace gmr::events
