// Shared helpers of the query-replace tests: pattern files from tools/data/patterns and flagged
// builders.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "model/core/builders.hpp"
#include "model/core/orbit.hpp"
#include "model/replace/edge_split.hpp"
#include "model/replace/pattern_folder.hpp"
#include "model/replace/unit_hex_positions.hpp"
#include "model/testing/source_tree.hpp"

namespace gmr::replace::testing {

inline std::filesystem::path patterns_dir(const std::string& set) {
  return std::filesystem::path(::gmr::testing::source_path("tools/data/patterns")) / set;
}
inline Pattern pattern_file(const std::string& set, const std::string& name) {
  Pattern p = load_pattern(patterns_dir(set) / (name + ".json"));
  p.name = name;
  return p;
}

// Every dart flagged: each dart of a polyhedron built by the builders is at a corner and on an
// original edge (Damiand & Nivoliers §7: inputs flagged at their corners).
inline FlaggedMap all_flagged(Map g) {
  FlaggedMap m{std::move(g), {}, {}};
  m.flag.assign(m.map.capacity(), 1);
  return m;
}

// A polycube with every dart flagged and the unit positions of its vertices.
inline FlaggedMap positioned_polycube(const std::vector<Voxel>& voxels) {
  FlaggedMap m = all_flagged(make_polycube(voxels));
  m.position = unit_hex_positions(m.map);
  return m;
}

// Splits every edge of m in k, one edge after the other (split_all_edges does it at once).
inline void split_each_edge(FlaggedMap& m, unsigned k) {
  for (Dart e : orbit_representatives(m.map, cell_type(m.map, 1))) split_edge(m, e, k);
}

// The per-dart positions, rounded to multiples of 1/scale and sorted (a multiset invariant under
// dart renumbering).
inline std::vector<std::array<long long, 3>> position_multiset(const FlaggedMap& m,
                                                               double scale = 1e6) {
  std::vector<std::array<long long, 3>> out;
  m.map.for_each_dart([&](Dart d) {
    const Vec3& p = m.position[d];
    out.push_back(
        {std::llround(p[0] * scale), std::llround(p[1] * scale), std::llround(p[2] * scale)});
  });
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace gmr::replace::testing
