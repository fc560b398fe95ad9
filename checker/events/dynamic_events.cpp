#include "checker/events/dynamic_events.hpp"

#include <algorithm>
#include <tuple>

#include "model/core/orbit.hpp"

namespace gmr::events {

namespace {
// The lowest dart of every orbit (visit_all_orbits meets orbits by increasing lowest dart).
std::vector<Dart> orbit_names(const Map& g, DimMask mask) {
  std::vector<Dart> name(g.capacity(), kNoDart);
  Dart current = kNoDart;
  visit_all_orbits(
      g, mask, [&](Dart r) { current = r; }, [&](Dart x) { name[x] = current; });
  return name;
}
}  // namespace

OrbitSnapshot snapshot(const Map& g, const OrbitType& o) {
  require_orbit_type(g, o);
  OrbitSnapshot s;
  s.orbit = o;
  s.name = orbit_names(g, o.mask());
  for (int i : o.dims()) s.links.push_back(g.links(i));
  return s;
}

std::vector<OrbitEvent> dynamic_events(const OrbitSnapshot& before, const Map& h,
                                       const std::vector<Dart>* touched) {
  const OrbitType& o = before.orbit;
  const DimMask om = o.mask();
  const std::vector<Dart>& gname = before.name;
  const std::vector<Dart> hname = orbit_names(h, o.mask());
  const Dart gcap = static_cast<Dart>(gname.size()), hcap = h.capacity();
  auto alive_g = [&](Dart d) { return d < gcap && gname[d] != kNoDart; };
  auto alive_h = [&](Dart d) { return d < hcap && h.alive(d); };
  // Per G-orbit (indexed by its name): the H-orbit of its first preserved dart, several H-orbits,
  // changed (a deleted dart or a changed <o>-link), non-modification listed. Per H-orbit: the same.
  std::vector<Dart> g_to(gcap, kNoDart), h_from(hcap, kNoDart);
  std::vector<char> g_many(gcap, 0), h_many(hcap, 0), g_changed(gcap, 0);
  std::vector<char> g_listed(gcap, touched ? 0 : 1);
  if (touched)
    for (Dart d : *touched)
      if (alive_g(d)) g_listed[gname[d]] = 1;
  for (Dart d = 0; d < gcap; ++d) {
    if (!alive_g(d)) continue;
    const Dart gn = gname[d];
    if (!alive_h(d)) {
      g_changed[gn] = 1;
      continue;
    }
    const Dart hn = hname[d];
    if (g_to[gn] == kNoDart)
      g_to[gn] = hn;
    else if (g_to[gn] != hn)
      g_many[gn] = 1;
    if (h_from[hn] == kNoDart)
      h_from[hn] = gn;
    else if (h_from[hn] != gn)
      h_many[hn] = 1;
    for (size_t p = 0; p < o.size(); ++p)
      if (before.links[p][d] != h.alpha(o[p], d)) g_changed[gn] = 1;
  }
  // The (G-orbit, H-orbit) pairs of the preserved darts of split G-orbits and merged H-orbits.
  std::vector<std::pair<Dart, Dart>> pairs;
  for (Dart d = 0; d < gcap; ++d)
    if (alive_g(d) && alive_h(d) && (g_many[gname[d]] || h_many[hname[d]]))
      pairs.emplace_back(gname[d], hname[d]);
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  std::vector<OrbitEvent> out;
  for (size_t k = 0; k < pairs.size();) {
    size_t e = k;
    while (e < pairs.size() && pairs[e].first == pairs[k].first) ++e;
    if (g_many[pairs[k].first]) {
      OrbitEvent ev{OrbitEventKind::Split, om, {pairs[k].first}, {}, EventStatus::Observed};
      for (size_t j = k; j < e; ++j) ev.after.push_back(pairs[j].second);
      out.push_back(std::move(ev));
    }
    k = e;
  }
  std::sort(pairs.begin(), pairs.end(), [](auto a, auto b) {
    return std::tie(a.second, a.first) < std::tie(b.second, b.first);
  });
  for (size_t k = 0; k < pairs.size();) {
    size_t e = k;
    while (e < pairs.size() && pairs[e].second == pairs[k].second) ++e;
    if (h_many[pairs[k].second]) {
      OrbitEvent ev{OrbitEventKind::Merge, om, {}, {pairs[k].second}, EventStatus::Observed};
      for (size_t j = k; j < e; ++j) ev.before.push_back(pairs[j].first);
      out.push_back(std::move(ev));
    }
    k = e;
  }
  for (Dart d = 0; d < gcap; ++d) {
    if (!alive_g(d) || gname[d] != d) continue;
    if (g_to[d] == kNoDart) {
      out.push_back({OrbitEventKind::Deletion, om, {d}, {}, EventStatus::Observed});
    } else if (!g_many[d] && !h_many[g_to[d]] && (g_changed[d] || g_listed[d])) {
      out.push_back({g_changed[d] ? OrbitEventKind::Modification : OrbitEventKind::NonModification,
                     om,
                     {d},
                     {g_to[d]},
                     EventStatus::Observed});
    }
  }
  for (Dart d = 0; d < hcap; ++d)
    if (alive_h(d) && hname[d] == d && h_from[d] == kNoDart)
      out.push_back({OrbitEventKind::Creation, om, {}, {d}, EventStatus::Observed});
  return out;
}

}  // namespace gmr::events
