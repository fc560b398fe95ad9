// The facts of a map kind, in one place (thesis Defs. 31-32): an n-G-map has labels 0..n, every
// dimension an involution, and the cycle constraint C(i,j) for labels i+2 <= j; an n-O-map has
// labels 1..n, dimension 1 a permutation (oriented, no non-orientation constraint) and the others
// involutions, and the cycle constraint on (1..n)_{+2}.
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

namespace gmr {

enum class MapKind : uint8_t { GMap, OMap };
const char* to_string(MapKind kind);

struct MapSpec {
  int n = 0;
  MapKind kind = MapKind::GMap;

  bool is_omap() const { return kind == MapKind::OMap; }
  // Lowest label: 0 for G-maps, 1 for O-maps.
  int lowest_dim() const { return is_omap() ? 1 : 0; }
  bool has_dim(int i) const { return i >= lowest_dim() && i <= n; }
  // Dimensions whose links must be involutions (non-orientation): all but 1 for an O-map.
  bool is_involutive_dim(int i) const { return has_dim(i) && !(is_omap() && i == 1); }
  // The labels lowest_dim()..n, in increasing order.
  std::vector<int> labels() const {
    std::vector<int> out;
    for (int i = lowest_dim(); i <= n; ++i) out.push_back(i);
    return out;
  }
  // The pairs (i, j), i + 2 <= j, on which the cycle constraint C(i,j) holds, in lexicographic
  // order.
  std::vector<std::pair<int, int>> cycle_pairs() const {
    std::vector<std::pair<int, int>> out;
    for (int i = lowest_dim(); i <= n; ++i)
      for (int j = i + 2; j <= n; ++j) out.emplace_back(i, j);
    return out;
  }
  friend bool operator==(const MapSpec&, const MapSpec&) = default;
};

}  // namespace gmr
