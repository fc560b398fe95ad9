#include "checker/events/event_log.hpp"

#include <algorithm>
#include <memory>
#include <numeric>

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

// The fate of a matched dart in the log of one orbit type: its G-orbit, its H-orbit (kNoDart when
// deleted), whether one of its <o>-links changed, whether its pattern orbit carries a flag.
struct Fate {
  Dart g, h;
  bool changed, flagged, unchanged_statically;
};

// An instance component of an incomplete pattern orbit: a dart of it, and its name once traversed.
struct Component {
  Dart rep, name;
};

// The working buffers of one call of Recorder::before or Recorder::after (never kept from one call
// to the next), one set per thread, reused from one application to the next: a detection on a
// local rule then allocates only its results.
struct Scratch {
  std::vector<uint32_t> parent;                     // name_complete: union-find over orbit indices
  std::vector<Dart> low;                            // name_complete: lowest dart per component
  std::vector<Component> comps;                     // name_by_traversal: instance components
  std::vector<uint32_t> slot_comp;                  // name_by_traversal: slot -> component
  std::vector<Dart> stack, visited;                 // traversal buffers
  std::vector<Dart> hname;                          // the R names of one orbit type
  std::vector<std::pair<Dart, bool>> split, merge;  // log_orbit_type
  std::vector<char> flagged;
  std::vector<Fate> fates;
  std::vector<std::pair<Dart, Dart>> into;
  std::vector<Dart> hs;
};
Scratch& scratch() {
  thread_local Scratch s;
  return s;
}

// Names (lowest darts) of the instances of one side's pattern orbits: names[v * s + b] for node v
// and orbit index b, `table` being the match (L, on G) or the comatch (R, on H).
class InstanceNamer {
 public:
  InstanceNamer(const Map& g, const OrbitGraph& O, const std::vector<Dart>& table, size_t nodes,
                Scratch& sc)
      : g_(g),
        O_(O),
        table_(table),
        nodes_(nodes),
        s_(O.size()),
        parent_(sc.parent),
        low_(sc.low),
        comps_(sc.comps),
        slot_comp_(sc.slot_comp),
        stack_(sc.stack),
        visited_(sc.visited) {}

  void names(const PatternOrbits& p, size_t& traversed, std::vector<Dart>& out) {
    out.assign(nodes_ * s_, kNoDart);
    comps_.clear();
    for (uint32_t c = 0; c < p.size(); ++c) {
      if (p.complete[c])
        name_complete(p, c, out);
      else
        list_components(p, c);
    }
    if (!comps_.empty()) name_by_traversal(p, out, traversed);
  }

 private:
  // The instance components of pattern orbit c: the orbit indices b joined along its positions
  // (parent_, by union-find), all its nodes at one b lying in one component (they are joined by
  // its explicit <o>-arcs). Each component lies in one orbit of the map.
  void components(const PatternOrbits& p, uint32_t c) {
    std::vector<uint32_t>& parent = parent_;
    parent.resize(s_);
    std::iota(parent.begin(), parent.end(), 0u);
    for (uint32_t k : p.positions[c])
      for (uint32_t b = 0; b < s_; ++b) parent[find(parent, b)] = find(parent, O_.neighbor(b, k));
  }

  // A complete pattern orbit: its instance components are whole orbits of the map.
  void name_complete(const PatternOrbits& p, uint32_t c, std::vector<Dart>& out) {
    components(p, c);
    std::vector<uint32_t>& parent = parent_;
    std::vector<Dart>& low = low_;
    low.assign(s_, kNoDart);
    for (uint32_t m : p.nodes[c])
      for (uint32_t b = 0; b < s_; ++b) {
        Dart& l = low[find(parent, b)];
        l = std::min(l, table_[m * s_ + b]);
      }
    for (uint32_t m : p.nodes[c])
      for (uint32_t b = 0; b < s_; ++b) out[m * s_ + b] = low[find(parent, b)];
  }

  // An incomplete pattern orbit: its components, each with a dart of it (a representative), to be
  // named by traversal; slot_comp_ gives the component of each of its slots.
  void list_components(const PatternOrbits& p, uint32_t c) {
    components(p, c);
    if (slot_comp_.size() < nodes_ * s_) slot_comp_.resize(nodes_ * s_);
    const uint32_t m0 = p.nodes[c].front();
    for (uint32_t b = 0; b < s_; ++b)
      if (find(parent_, b) == b) {
        slot_comp_[m0 * s_ + b] = static_cast<uint32_t>(comps_.size());
        comps_.push_back({table_[m0 * s_ + b], kNoDart});
      }
    for (uint32_t m : p.nodes[c])
      for (uint32_t b = 0; b < s_; ++b)
        slot_comp_[m * s_ + b] = slot_comp_[m0 * s_ + find(parent_, b)];
  }

  // One traversal per orbit of the map holding components of incomplete pattern orbits (of any
  // of them): the orbit's lowest dart names every component whose representative it visits. The
  // cost is that of the orbits traversed plus, per traversal, one marker test per component:
  // never a look-up in a structure the size of the map.
  void name_by_traversal(const PatternOrbits& p, std::vector<Dart>& out, size_t& traversed) {
    ScopedMarker seen(g_);
    for (size_t i = 0; i < comps_.size(); ++i) {
      if (comps_[i].name != kNoDart) continue;
      visited_.clear();
      visit_orbit_marked(g_, p.orbit, comps_[i].rep, seen.id(), stack_,
                         [&](Dart x) { visited_.push_back(x); });
      const Dart low = *std::min_element(visited_.begin(), visited_.end());
      for (size_t j = i; j < comps_.size(); ++j)
        if (comps_[j].name == kNoDart && seen.test(comps_[j].rep)) comps_[j].name = low;
      for (Dart x : visited_) seen.unmark(x);
      traversed += visited_.size();
    }
    seen.set_clean();
    for (uint32_t c = 0; c < p.size(); ++c)
      if (!p.complete[c])
        for (uint32_t m : p.nodes[c])
          for (uint32_t b = 0; b < s_; ++b) out[m * s_ + b] = comps_[slot_comp_[m * s_ + b]].name;
  }

  const Map& g_;
  const OrbitGraph& O_;
  const std::vector<Dart>& table_;
  size_t nodes_, s_;
  std::vector<uint32_t>& parent_;
  std::vector<Dart>& low_;
  std::vector<Component>& comps_;       // components of the incomplete pattern orbits
  std::vector<uint32_t>& slot_comp_;    // slot -> its component (incomplete pattern orbits only)
  std::vector<Dart>&stack_, &visited_;  // traversal buffers, reused across orbits
};

class Recorder {
 public:
  Recorder(const RuleScheme& s, const StaticEvents& st) : s_(s), st_(st) {}

  // Step 1 (G before the rewrite).
  void before(const Map& g, const OrbitGraph& O, const SchemeApplication& res) {
    O_ = &O;
    ns_ = O.size();
    match_ = &res.match;
    const std::vector<Dart>& M_ = res.match;
    dims_ = g.dimension() + 1;
    // The links of the matched darts before the rewrite, in the dimensions of the analysed orbit
    // types only (each other link array would be read for nothing).
    DimMask used = 0;
    for (const auto& t : st_.orbits) used |= t.orbit.mask();
    old_.resize(M_.size() * dims_);
    for (int i = 0; i < dims_; ++i) {
      if (!((used >> i) & 1u)) continue;
      const std::vector<Dart>& link = g.links(i);
      for (size_t k = 0; k < M_.size(); ++k) old_[k * dims_ + i] = link[M_[k]];
    }
    InstanceNamer namer(g, O, M_, s_.left.size(), scratch());
    logs_.clear();
    logs_.resize(st_.orbits.size());
    gname_.resize(st_.orbits.size());
    for (size_t t = 0; t < st_.orbits.size(); ++t) {
      logs_[t].orbit = st_.orbits[t].orbit;
      namer.names(st_.orbits[t].left, logs_[t].traversed, gname_[t]);
    }
  }

  // Steps 3 and 4 (H after the rewrite).
  std::vector<OrbitTypeLog> after(const Map& h, const SchemeApplication& res) {
    T_ = &res.comatch;
    match_ = &res.match;
    Scratch& sc = scratch();
    InstanceNamer namer(h, *O_, res.comatch, s_.right.size(), sc);
    for (size_t t = 0; t < st_.orbits.size(); ++t) {
      namer.names(st_.orbits[t].right, logs_[t].traversed, sc.hname);
      log_orbit_type(h, st_.orbits[t], gname_[t], sc.hname, logs_[t], sc);
    }
    return std::move(logs_);
  }

 private:
  Dart l_slot(uint32_t v, uint32_t b) const { return v * static_cast<uint32_t>(ns_) + b; }

  // Orbit names with a flag (certain), sorted by name, one entry per name (certain if any is).
  static void settle(std::vector<std::pair<Dart, bool>>& v) {
    std::sort(v.begin(), v.end());
    size_t w = 0;
    for (size_t k = 0; k < v.size(); ++k) {
      if (w > 0 && v[w - 1].first == v[k].first)
        v[w - 1].second = v[w - 1].second || v[k].second;
      else
        v[w++] = v[k];
    }
    v.resize(w);
  }
  static const std::pair<Dart, bool>* lookup(const std::vector<std::pair<Dart, bool>>& v,
                                             Dart name) {
    auto it = std::lower_bound(v.begin(), v.end(), std::make_pair(name, false));
    return it != v.end() && it->first == name ? &*it : nullptr;
  }

  void log_orbit_type(const Map& h, const OrbitTypeEvents& te, const std::vector<Dart>& gname,
                      const std::vector<Dart>& hname, OrbitTypeLog& log, Scratch& sc) const {
    const OrbitType& o = te.orbit;
    const DimMask om = o.mask();
    const std::vector<Dart>& M_ = *match_;
    auto& split = sc.split;  // G-orbits split (certain)
    auto& merge = sc.merge;  // H-orbits merged (certain)
    split.clear();
    merge.clear();
    auto& flagged = sc.flagged;  // L pattern orbits with a split or merge flag
    flagged.assign(te.left.size(), 0);
    for (uint32_t ei = 0; ei < te.events.size(); ++ei) {
      const PatternEvent& e = te.events[ei];
      if (e.kind == PatternEventKind::Deletion || e.kind == PatternEventKind::Creation) {
        const bool del = e.kind == PatternEventKind::Deletion;
        // Created and deleted pattern orbits are complete: each instance component is a whole
        // orbit, logged once, at the dart that names it.
        const auto& nodes = del ? te.left.nodes[e.left[0]] : te.right.nodes[e.right[0]];
        const std::vector<Dart>& table = del ? M_ : *T_;
        const std::vector<Dart>& name = del ? gname : hname;
        for (uint32_t m : nodes)
          for (uint32_t b = 0; b < ns_; ++b) {
            const Dart n = name[l_slot(m, b)];
            if (table[l_slot(m, b)] != n) continue;
            log.events.push_back({del ? OrbitEventKind::Deletion : OrbitEventKind::Creation, om,
                                  del ? DartList{n} : DartList{}, del ? DartList{} : DartList{n},
                                  EventStatus::Certain});
          }
        continue;
      }
      const bool sp = is_split(e.kind), mg = is_merge(e.kind);
      if (!sp && !mg) continue;
      for (uint32_t c : e.left) flagged[c] = true;
      const bool certain = e.certainty == Certainty::Certain;
      for (const InstancePair& p : e.pairs) {
        const uint32_t ra = st_.right_of[p.a], rb = st_.right_of[p.b];
        for (uint32_t b = 0; b < ns_; ++b) {
          const uint32_t b2 = p.position < 0 ? b : O_->neighbor(b, static_cast<size_t>(p.position));
          if (p.a == p.b && b2 < b) continue;  // the pair (b2, b), already compared
          // Splits on H after the rewrite, merges on G before it.
          const Dart na = sp ? hname[l_slot(ra, b)] : gname[l_slot(p.a, b)];
          const Dart nb = sp ? hname[l_slot(rb, b2)] : gname[l_slot(p.b, b2)];
          const bool different = na != nb;
          if (!certain)
            log.checks.push_back(
                {ei, sp ? 'H' : 'G', M_[l_slot(p.a, b)], M_[l_slot(p.b, b2)], different});
          if (!different) continue;
          (sp ? split : merge)
              .emplace_back(sp ? gname[l_slot(p.a, b)] : hname[l_slot(ra, b)], certain);
        }
      }
    }
    settle(split);
    settle(merge);
    // The fate of every matched dart.
    auto& fates = sc.fates;
    fates.clear();
    auto& into = sc.into;  // (H-orbit, G-orbit) of the preserved matched darts
    into.clear();
    // A capacity hint: merges, splits and (non-)modifications name matched darts.
    log.events.reserve(log.events.size() + s_.left.size() * ns_);
    for (uint32_t v = 0; v < s_.left.size(); ++v) {
      const uint32_t r = st_.right_of[v];
      const bool fl = flagged[te.left.class_of[v]];
      const bool nm = te.residual[te.left.class_of[v]] == PatternEventKind::NonModification;
      for (uint32_t b = 0; b < ns_; ++b) {
        const Dart gn = gname[l_slot(v, b)];
        if (r == StaticEvents::kDeletedNode) {
          fates.push_back({gn, kNoDart, true, fl, false});
          continue;
        }
        const Dart hn = hname[l_slot(r, b)];
        const Dart d = M_[l_slot(v, b)];
        bool ch = false;
        for (int i : o.dims()) ch = ch || old_[l_slot(v, b) * dims_ + i] != h.alpha(i, d);
        fates.push_back({gn, hn, ch, fl, nm});
        into.emplace_back(hn, gn);
      }
    }
    std::sort(into.begin(), into.end());
    into.erase(std::unique(into.begin(), into.end()), into.end());
    for (auto [hn, certain] : merge) {
      OrbitEvent ev{OrbitEventKind::Merge,
                    om,
                    {},
                    {hn},
                    certain ? EventStatus::Certain : EventStatus::Confirmed};
      for (auto it = std::lower_bound(into.begin(), into.end(), std::make_pair(hn, Dart(0)));
           it != into.end() && it->first == hn; ++it)
        ev.before.push_back(it->second);
      log.events.push_back(std::move(ev));
    }
    std::sort(fates.begin(), fates.end(), [](const Fate& a, const Fate& b) { return a.g < b.g; });
    std::vector<Dart>& hs = sc.hs;
    for (size_t k = 0; k < fates.size();) {
      const Dart gn = fates[k].g;
      bool changed = false, fl = false, nm = true;
      hs.clear();
      for (; k < fates.size() && fates[k].g == gn; ++k) {
        changed = changed || fates[k].changed;
        fl = fl || fates[k].flagged;
        nm = nm && fates[k].unchanged_statically;
        if (fates[k].h != kNoDart) hs.push_back(fates[k].h);
      }
      if (hs.empty()) continue;  // deleted (logged above)
      std::sort(hs.begin(), hs.end());
      hs.erase(std::unique(hs.begin(), hs.end()), hs.end());
      if (const auto* sp = lookup(split, gn)) {
        log.events.push_back({OrbitEventKind::Split,
                              om,
                              {gn},
                              hs,
                              sp->second ? EventStatus::Certain : EventStatus::Confirmed});
        continue;
      }
      if (lookup(merge, hs.front())) continue;  // part of a merge
      log.events.push_back(
          {changed ? OrbitEventKind::Modification : OrbitEventKind::NonModification,
           om,
           {gn},
           {hs.front()},
           fl || changed == nm ? EventStatus::Refuted : EventStatus::Certain});
    }
  }

  const RuleScheme& s_;
  const StaticEvents& st_;
  const OrbitGraph* O_ =
      nullptr;  // the hook orbit graph, alive from before_rewrite to after_rewrite
  size_t ns_ = 0;
  int dims_ = 0;
  const std::vector<Dart>* match_ =
      nullptr;  // the match, alive from before_rewrite to after_rewrite
  std::vector<Dart> old_;
  const std::vector<Dart>* T_ = nullptr;  // the comatch, after the rewrite
  std::vector<OrbitTypeLog> logs_;
  std::vector<std::vector<Dart>> gname_;
};

}  // namespace

struct EventRecorder::Impl {
  Recorder rec;
  Impl(const RuleScheme& s, const StaticEvents& st) : rec(s, st) {}
};

EventRecorder::EventRecorder(const RuleScheme& s, const StaticEvents& analysis,
                             scheme::ApplicationObserver* also)
    : s_(s), hook_nodes_(s.hook_nodes()), impl_(std::make_unique<Impl>(s, analysis)), also_(also) {
  if (analysis.rule != s.name || analysis.dimension != s.dimension)
    throw Error(ErrorCode::Usage, "the static events are those of rule \"" + analysis.rule + "\"",
                "scheme " + s.name);
  for (const auto& t : analysis.orbits)
    if (t.left.class_of.size() != s.left.size() || t.right.class_of.size() != s.right.size() ||
        analysis.right_of.size() != s.left.size())
      throw Error(ErrorCode::Usage, "the static events do not match the scheme's nodes",
                  "scheme " + s.name);
}

EventRecorder::~EventRecorder() = default;

// Merges are checked on G, before the rewrite; `also` (embedding propagation) sees both phases.
void EventRecorder::before_rewrite(const Map& before, const SchemeApplication& res,
                                   const OrbitGraph& O) {
  impl_->rec.before(before, O, res);
  if (also_) also_->before_rewrite(before, res, O);
}

// Splits are checked on H, after it; the hook orbit O is still alive here.
void EventRecorder::after_rewrite(const Map& after, const SchemeApplication& res,
                                  const OrbitGraph& O) {
  EventLog log;
  log.rule = s_.name;
  // Hook k at orbit dart 0: the reference hook starts the hook orbit, and the orbit isomorphism of
  // another hook's orbit sends it to that hook (scheme_engine.hpp, step 2).
  for (uint32_t v : hook_nodes_) log.hooks.push_back(res.match_at(v, 0));
  log.orbits = impl_->rec.after(after, res);
  logs_.push_back(std::move(log));
  if (also_) also_->after_rewrite(after, res, O);
}

}  // namespace gmr::events
