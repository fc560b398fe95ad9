#include "model/replace/adaptive_hex_meshing.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>

#include "model/core/builders.hpp"
#include "model/core/error.hpp"
#include "model/core/orbit.hpp"
#include "model/core/position.hpp"
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

// The volumes of the map: per dart its volume, per volume one dart, its box and its level.
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
  for (Dart rep : orbit_representatives(g, cell_type(g, 3))) {
    const uint32_t k = static_cast<uint32_t>(v.dart.size());
    Vec3 lo = m.position[rep], hi = lo;
    for (Dart x : orbit(g, cell_type(g, 3), rep)) {
      v.of[x] = k;
      for (int c = 0; c < 3; ++c) {
        lo[c] = std::min(lo[c], m.position[x][c]);
        hi[c] = std::max(hi[c], m.position[x][c]);
      }
    }
    v.dart.push_back(rep);
    v.lo.push_back(lo);
    v.hi.push_back(hi);
    v.level.push_back(static_cast<int>(std::lround(std::log2(root / (hi[0] - lo[0])))));
  }
  return v;
}

// Cuts the hexahedra of `group` (one dart each, all of one level) into 2x2x2: the e-pattern on
// their edges between two corners (flagged ends), f-patterns on their faces (one dart per face),
// the v-pattern on the volumes; then flags every dart of the new hexahedra.
void refine_group(FlaggedMap& m, const PatternStore& store, const std::vector<Dart>& group, MeshingLevel& r) {
  Map& g = m.map;
  for (Dart h : group)
    for (Dart x : orbit(g, cell_type(g, 3), h))
      if (m.flag[x] && m.flag[g.alpha(0, x)]) split_edge(m, x, 2);
  std::vector<Dart> faces;
  std::vector<uint8_t> seen(g.capacity(), 0);
  for (Dart h : group)
    for (Dart x : orbit(g, cell_type(g, 3), h)) {
      if (seen[x]) continue;
      for (Dart y : orbit(g, cell_type(g, 2), x)) seen[y] = 1;
      faces.push_back(x);
    }
  r.face_replacements += query_replace(m, store, 2, {}, {}, {}, &faces).replaced();
  // The darts of the new hexahedra: the volumes' darts now and the copies.
  std::vector<Dart> old;
  for (Dart h : group)
    for (Dart x : orbit(g, cell_type(g, 3), h)) old.push_back(x);
  const Dart first_new = g.capacity();
  const QueryReplaceReport vr = query_replace(m, store, 3, {}, {}, {}, &group);
  if (!vr.unmatched.empty())
    throw Error(ErrorCode::InvalidMap, "a hexahedron to refine matched no pattern (unbalanced mesh)",
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
  if (g.dimension() != 3 || !m.positioned()) throw Error(ErrorCode::InvalidMap, "adaptive meshing needs a positioned 3-G-map");
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
    // The hexahedra of the finest level meeting the surface, then the balance.
    std::vector<uint8_t> chosen(v.dart.size(), 0);
    std::vector<uint32_t> refine;
    for (uint32_t k = 0; k < v.dart.size(); ++k)
      if (v.level[k] == l - 1 && meets_surface(v.lo[k], v.hi[k])) {
        chosen[k] = 1;
        refine.push_back(k);
      }
    const size_t wanted = refine.size();
    for (size_t i = 0; i < refine.size(); ++i) {
      const uint32_t k = refine[i];
      for (Dart x : orbit(g, cell_type(g, 3), v.dart[k]))
        for (Dart y : orbit(g, vertex_orbit_type(g), x)) {
          const uint32_t n = v.of[y];
          if (!chosen[n] && v.level[n] < v.level[k]) {
            chosen[n] = 1;
            refine.push_back(n);
          }
        }
    }
    r.balanced = refine.size() - wanted;
    // Coarsest first: a hexahedron added for the balance is cut before its finer neighbours, so
    // that their faces never cut its faces a second time.
    std::stable_sort(refine.begin(), refine.end(), [&](uint32_t a, uint32_t b) { return v.level[a] < v.level[b]; });
    for (size_t begin = 0; begin < refine.size();) {
      size_t end = begin;
      while (end < refine.size() && v.level[refine[end]] == v.level[refine[begin]]) ++end;
      std::vector<Dart> group;
      for (size_t i = begin; i < end; ++i) group.push_back(v.dart[refine[i]]);
      refine_group(m, store, group, r);
      begin = end;
    }
    r.volumes = count_cells(g, 3);
    r.seconds = cpu_seconds() - t0;
    out.push_back(r);
  }
  return out;
}

}  // namespace gmr::replace
