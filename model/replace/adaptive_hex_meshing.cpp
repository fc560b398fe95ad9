#include "model/replace/adaptive_hex_meshing.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <functional>

#include "model/core/builders.hpp"
#include "model/core/error.hpp"
#include "model/core/orbit.hpp"
#include "model/core/position.hpp"
#include "model/core/validity.hpp"
#include "model/replace/edge_split.hpp"
#include "model/replace/query_replace.hpp"
#include "model/replace/unit_hex_positions.hpp"

namespace gmr::replace {

namespace {

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
}

// The volumes of the map, numbered in the order of their smallest dart: per dart its volume, per
// volume its smallest dart, its box and its level.
struct Volumes {
  std::vector<uint32_t> of;
  std::vector<Dart> dart;
  std::vector<Vec3> lo, hi;
  std::vector<int> level;
};

Volumes volumes_of(const FlaggedMap& m, double root) {
  const Map& g = m.map;
  Volumes v;
  v.of.assign(g.capacity(), UINT32_MAX);
  visit_all_orbits(
      g, cell_type(g, 3).mask(),
      [&](Dart rep) {
        v.dart.push_back(rep);
        v.lo.push_back(m.position[rep]);
        v.hi.push_back(m.position[rep]);
      },
      [&](Dart x) {
        const uint32_t k = static_cast<uint32_t>(v.dart.size() - 1);
        v.of[x] = k;
        for (int c = 0; c < 3; ++c) {
          v.lo[k][c] = std::min(v.lo[k][c], m.position[x][c]);
          v.hi[k][c] = std::max(v.hi[k][c], m.position[x][c]);
        }
      });
  for (size_t k = 0; k < v.dart.size(); ++k)
    v.level.push_back(static_cast<int>(std::lround(std::log2(root / (v.hi[k][0] - v.lo[k][0])))));
  return v;
}

// The hexahedra to refine at a level (volume numbers): first those meeting the surface, then those
// refined for the balance.
struct Refinement {
  std::vector<uint32_t> hexahedra;
  size_t meeting = 0;  // the first `meeting` hexahedra meet the surface
};

// The hexahedra to refine at level l: those of level l - 1 meeting the surface, then, recursively,
// every coarser hexahedron sharing a vertex with one to refine (the balance). Each vertex of a
// hexahedron is visited once per hexahedron (its darts in the hexahedron marked through their
// <1, 2>-orbit, its corner), its whole vertex orbit read for the volumes around it.
Refinement hexahedra_to_refine(const Map& g, const Volumes& v, int l,
                               const BoxTest& meets_surface) {
  std::vector<uint8_t> chosen(v.dart.size(), 0);
  std::vector<uint32_t> refine;
  for (uint32_t k = 0; k < v.dart.size(); ++k)
    if (v.level[k] == l - 1 && meets_surface(v.lo[k], v.hi[k])) {
      chosen[k] = 1;
      refine.push_back(k);
    }
  const size_t meeting = refine.size();
  const DimMask volume = cell_type(g, 3).mask(), corner = DimMask(0b0110),
                vertex = vertex_orbit_type(g).mask();
  ScopedMarker in_volume(g), at_corner(g), at_vertex(g);
  std::vector<Dart> darts, corners, around, stack;
  for (size_t i = 0; i < refine.size(); ++i) {
    const uint32_t k = refine[i];
    darts.clear();
    visit_orbit_marked(g, volume, v.dart[k], in_volume.id(), stack,
                       [&](Dart x) { darts.push_back(x); });
    corners.clear();
    for (Dart x : darts) {
      if (at_corner.test(x)) continue;
      visit_orbit_marked(g, corner, x, at_corner.id(), stack,
                         [&](Dart y) { corners.push_back(y); });
      around.clear();
      visit_orbit_marked(g, vertex, x, at_vertex.id(), stack, [&](Dart y) { around.push_back(y); });
      for (Dart y : around) {
        at_vertex.unmark(y);
        const uint32_t n = v.of[y];
        if (!chosen[n] && v.level[n] < v.level[k]) {
          chosen[n] = 1;
          refine.push_back(n);
        }
      }
    }
    for (Dart x : darts) in_volume.unmark(x);
    for (Dart x : corners) at_corner.unmark(x);
  }
  in_volume.set_clean();
  at_corner.set_clean();
  at_vertex.set_clean();
  return {std::move(refine), meeting};
}

// The darts of the volumes of `group` (one dart each), volume by volume.
std::vector<Dart> volume_darts(const Map& g, const std::vector<Dart>& group) {
  std::vector<Dart> darts, stack;
  ScopedMarker seen(g);
  for (Dart h : group)
    visit_orbit_marked(g, cell_type(g, 3).mask(), h, seen.id(), stack,
                       [&](Dart x) { darts.push_back(x); });
  for (Dart x : darts) seen.unmark(x);
  seen.set_clean();
  return darts;
}

// One dart per <mask>-orbit of `darts`: the first of its darts, in their order, that is `wanted`.
std::vector<Dart> orbits_met(const Map& g, DimMask mask, const std::vector<Dart>& darts,
                             const std::function<bool(Dart)>& wanted) {
  std::vector<Dart> reps, met, stack;
  ScopedMarker seen(g);
  for (Dart x : darts)
    if (!seen.test(x) && wanted(x)) {
      reps.push_back(x);
      visit_orbit_marked(g, mask, x, seen.id(), stack, [&](Dart y) { met.push_back(y); });
    }
  for (Dart x : met) seen.unmark(x);
  seen.set_clean();
  return reps;
}

// Cuts the hexahedra of `group` (one dart each, all of one level) into 2x2x2: the e-pattern on
// their edges between two corners (flagged ends), f-patterns on their faces (one dart per face),
// the v-pattern on the volumes; then flags every dart of the new hexahedra. The map is valid
// before (refine_adaptively checks it) and each step keeps it valid, so the steps do not check it.
void refine_group(FlaggedMap& m, const PatternStore& store, const std::vector<Dart>& group,
                  MeshingLevel& r) {
  Map& g = m.map;
  const std::vector<Dart> edges =
      orbits_met(g, cell_type(g, 1).mask(), volume_darts(g, group),
                 [&](Dart x) { return m.flag[x] && m.flag[g.alpha(0, x)]; });
  split_edges(m, edges, 2);
  const std::vector<Dart> faces =
      orbits_met(g, cell_type(g, 2).mask(), volume_darts(g, group), [](Dart) { return true; });
  r.face_replacements +=
      query_replace(m, store, 2, {}, {}, {}, &faces, Precondition::AssumeValid).replaced();
  // The darts of the new hexahedra: the volumes' darts now and the copies.
  const std::vector<Dart> old = volume_darts(g, group);
  const Dart first_new = g.capacity();
  const QueryReplaceReport vr =
      query_replace(m, store, 3, {}, {}, {}, &group, Precondition::AssumeValid);
  if (!vr.unmatched.empty())
    throw Error(ErrorCode::InvalidMap,
                "a hexahedron to refine matched no pattern (unbalanced mesh)",
                "dart " + std::to_string(vr.unmatched.front()));
  r.volume_replacements += vr.replaced();
  m.resize_flags();
  for (Dart x : old) m.flag[x] = 1;
  for (Dart x = first_new; x < g.capacity(); ++x) m.flag[x] = 1;
}

}  // namespace

FlaggedMap box_hexahedron(const Vec3& lo, double size) {
  FlaggedMap m{make_polycube({{0, 0, 0}}), {}, {}};
  m.flag.assign(m.map.capacity(), 1);
  m.position = unit_hex_positions(m.map, size);
  // unit_hex_positions may give the mirror image, translated: move it to [lo, lo + size]^3.
  Vec3 least = m.position[0];
  for (const Vec3& p : m.position)
    for (int c = 0; c < 3; ++c) least[c] = std::min(least[c], p[c]);
  for (Vec3& p : m.position)
    for (int c = 0; c < 3; ++c) p[c] += lo[c] - least[c];
  return m;
}

std::vector<MeshingLevel> refine_adaptively(FlaggedMap& m, const PatternStore& store, int levels,
                                            const BoxTest& meets_surface) {
  Map& g = m.map;
  if (g.dimension() != 3 || !m.positioned())
    throw Error(ErrorCode::InvalidMap, "adaptive meshing needs a positioned 3-G-map");
  const ValidityReport valid = check_validity(g, 1);
  if (!valid.ok())
    throw Error(ErrorCode::InvalidMap,
                "the map is not valid: " + to_text(valid.violations.front()));
  m.resize_flags();
  double root = 0;
  {
    Vec3 lo = m.position[0], hi = lo;
    g.for_each_dart([&](Dart d) {
      for (int c = 0; c < 3; ++c) {
        lo[c] = std::min(lo[c], m.position[d][c]);
        hi[c] = std::max(hi[c], m.position[d][c]);
      }
    });
    root = hi[0] - lo[0];
  }
  std::vector<MeshingLevel> out;
  for (int l = 1; l <= levels; ++l) {
    const double t0 = cpu_seconds();
    MeshingLevel r;
    r.level = l;
    const Volumes v = volumes_of(m, root);
    Refinement chosen = hexahedra_to_refine(g, v, l, meets_surface);
    std::vector<uint32_t>& refine = chosen.hexahedra;
    r.balanced = refine.size() - chosen.meeting;
    // Coarsest first: a hexahedron added for the balance is cut before its finer neighbours, so
    // that their faces never cut its faces a second time.
    std::stable_sort(refine.begin(), refine.end(),
                     [&](uint32_t a, uint32_t b) { return v.level[a] < v.level[b]; });
    for (size_t begin = 0; begin < refine.size();) {
      size_t end = begin;
      while (end < refine.size() && v.level[refine[end]] == v.level[refine[begin]]) ++end;
      std::vector<Dart> group;
      for (size_t i = begin; i < end; ++i) group.push_back(v.dart[refine[i]]);
      refine_group(m, store, group, r);
      begin = end;
    }
    r.seconds = cpu_seconds() - t0;
    r.volumes = count_cells(g, 3);  // for the report, not timed
    out.push_back(r);
  }
  return out;
}

}  // namespace gmr::replace
