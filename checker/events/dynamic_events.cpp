#include "checker/events/dynamic_events.hpp"

#include <algorithm>
#include <unordered_set>

#include "model/core/orbit.hpp"

namespace gmr::events {

namespace {
// The lowest dart of every orbit (visit_all_orbits meets orbits by increasing lowest dart).
std::vector<Dart> orbit_names(const GMap& g, DimMask mask) {
  std::vector<Dart> name(g.capacity(), kNoDart);
  Dart current = kNoDart;
  visit_all_orbits(
      g, mask, [&](Dart r) { current = r; }, [&](Dart x) { name[x] = current; });
  return name;
}
}  // namespace

OrbitSnapshot snapshot(const GMap& g, const OrbitType& o) {
  require_orbit_type(g, o);
  OrbitSnapshot s;
  s.orbit = o;
  s.name = orbit_names(g, o.mask());
  for (int i : o.dims()) s.links.push_back(g.links(i));
  return s;
}

std::vector<OrbitEvent> dynamic_events(const OrbitSnapshot& before, const GMap& h) {
  const OrbitType& o = before.orbit;
  const std::vector<Dart>& gname = before.name;
  const std::vector<Dart> hname = orbit_names(h, o.mask());
  const Dart gcap = static_cast<Dart>(gname.size()), hcap = h.capacity();
  auto alive_g = [&](Dart d) { return d < gcap && gname[d] != kNoDart; };
  auto alive_h = [&](Dart d) { return d < hcap && h.alive(d); };
  // Per G-orbit: holds a preserved dart; changed (a deleted dart or a changed <o>-link).
  std::vector<char> g_kept(gcap, 0), g_changed(gcap, 0), h_kept(hcap, 0);
  std::vector<std::pair<Dart, Dart>> pairs;  // (G-orbit, H-orbit) of each preserved dart
  for (Dart d = 0; d < gcap; ++d) {
    if (!alive_g(d)) continue;
    if (!alive_h(d)) {
      g_changed[gname[d]] = 1;
      continue;
    }
    g_kept[gname[d]] = 1;
    h_kept[hname[d]] = 1;
    pairs.emplace_back(gname[d], hname[d]);
    for (size_t p = 0; p < o.size(); ++p)
      if (before.links[p][d] != h.alpha(o[p], d)) g_changed[gname[d]] = 1;
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  std::vector<OrbitEvent> out;
  // Splits, and the number of H-orbits of each G-orbit.
  std::vector<uint32_t> g_out(gcap, 0), h_in(hcap, 0);
  for (auto [gn, hn] : pairs) {
    ++g_out[gn];
    ++h_in[hn];
  }
  for (size_t k = 0; k < pairs.size();) {
    size_t e = k;
    while (e < pairs.size() && pairs[e].first == pairs[k].first) ++e;
    if (e - k > 1) {
      OrbitEvent ev{OrbitEventKind::Split, o, {pairs[k].first}, {}, EventStatus::Observed};
      for (size_t j = k; j < e; ++j) ev.after.push_back(pairs[j].second);
      std::sort(ev.after.begin(), ev.after.end());
      out.push_back(std::move(ev));
    } else if (h_in[pairs[k].second] == 1) {
      const bool same = !g_changed[pairs[k].first];
      out.push_back({same ? OrbitEventKind::NonModification : OrbitEventKind::Modification, o,
                     {pairs[k].first}, {pairs[k].second}, EventStatus::Observed});
    }
    k = e;
  }
  std::sort(pairs.begin(), pairs.end(), [](auto a, auto b) {
    return std::tie(a.second, a.first) < std::tie(b.second, b.first);
  });
  for (size_t k = 0; k < pairs.size();) {
    size_t e = k;
    while (e < pairs.size() && pairs[e].second == pairs[k].second) ++e;
    if (e - k > 1) {
      OrbitEvent ev{OrbitEventKind::Merge, o, {}, {pairs[k].second}, EventStatus::Observed};
      for (size_t j = k; j < e; ++j) ev.before.push_back(pairs[j].first);
      std::sort(ev.before.begin(), ev.before.end());
      out.push_back(std::move(ev));
    }
    k = e;
  }
  for (Dart d = 0; d < gcap; ++d)
    if (alive_g(d) && gname[d] == d && !g_kept[d])
      out.push_back({OrbitEventKind::Deletion, o, {d}, {}, EventStatus::Observed});
  for (Dart d = 0; d < hcap; ++d)
    if (alive_h(d) && hname[d] == d && !h_kept[d])
      out.push_back({OrbitEventKind::Creation, o, {}, {d}, EventStatus::Observed});
  return out;
}

std::vector<OrbitEvent> touched_only(const std::vector<OrbitEvent>& events, const OrbitSnapshot& before,
                                     const std::vector<Dart>& darts) {
  std::unordered_set<Dart> names;
  for (Dart d : darts)
    if (d < before.name.size() && before.name[d] != kNoDart) names.insert(before.name[d]);
  std::vector<OrbitEvent> out;
  for (const auto& e : events)
    if (e.kind != OrbitEventKind::NonModification || names.count(e.before.front())) out.push_back(e);
  return out;
}

}  // namespace gmr::events
