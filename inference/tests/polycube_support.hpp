// Polycube examples for inference (thesis §7.4.4, inference paper §9.2): a polycube whose every
// voxel is replaced by the voxels of a subdivision pattern, the dart mapping that preserves each
// before dart in the pattern's corner voxel at its own corner, and positions (each voxel a unit
// cube, the pattern scaled into it).
#pragma once
#include <array>
#include <map>
#include <vector>

#include "inference/dart_mapping.hpp"
#include "model/core/builders.hpp"
#include "model/core/embedded_map.hpp"
#include "model/core/orbit.hpp"

namespace gmr::inference::test::polycube {

inline constexpr Dart kVoxelDarts = 48;  // make_polycube lays every voxel out identically

// Corner (x, y, z in {0,1}) of every local dart of a voxel, found topologically: in the polycube
// {(0,0,0), e_a}, the darts of voxel 0 whose vertex (<1,2>-orbit in the volume) touches the glued
// face x_a = 1 are the ones with coordinate a = 1.
inline std::vector<std::array<int, 3>> local_corners() {
  std::vector<std::array<int, 3>> corner(kVoxelDarts, {0, 0, 0});
  for (size_t a = 0; a < 3; ++a) {
    Voxel other{0, 0, 0};
    other[a] = 1;
    const Map two = make_polycube({{0, 0, 0}, other});
    for (Dart d = 0; d < kVoxelDarts; ++d)
      for (Dart e : orbit(two, OrbitType{1, 2}, d))
        if (!two.is_free(3, e)) corner[d][a] = 1;
  }
  return corner;
}

// Every voxel of `cubes` replaced by the voxels of `pattern` (a side x side x side grid): the
// pattern voxels of cube k at k * |pattern| + i.
inline std::vector<Voxel> subdivided(const std::vector<Voxel>& cubes,
                                     const std::vector<Voxel>& pattern, int side) {
  std::vector<Voxel> out;
  for (const Voxel& c : cubes)
    for (const Voxel& p : pattern)
      out.push_back({side * c[0] + p[0], side * c[1] + p[1], side * c[2] + p[2]});
  return out;
}

// The level-1 Menger voxels of every voxel of `cubes`.
inline std::vector<Voxel> menger_of(const std::vector<Voxel>& cubes) {
  return subdivided(cubes, menger_voxels(1), 3);
}

// A subdivision of every voxel of `cubes` by `pattern`, voxels in a side x side x side grid.
struct PolycubeSubdivision {
  std::vector<Voxel> cubes, pattern, sub;  // sub: pattern voxels of cube k at k * |pattern| + i
  int side = 1;
  Map before{3}, after{3};
  DartMapping mapping;  // before dart -> the same local dart in the pattern voxel at its corner

  PolycubeSubdivision(std::vector<Voxel> cubes_, std::vector<Voxel> pattern_, int side_)
      : cubes(std::move(cubes_)), pattern(std::move(pattern_)), side(side_) {
    sub = subdivided(cubes, pattern, side);
    before = make_polycube(cubes);
    after = make_polycube(sub);
    std::map<Voxel, Dart> index;
    for (size_t k = 0; k < sub.size(); ++k) index[sub[k]] = static_cast<Dart>(k);
    const auto corner = local_corners();
    for (size_t k = 0; k < cubes.size(); ++k)
      for (Dart i = 0; i < kVoxelDarts; ++i) {
        Voxel s{};
        for (size_t a = 0; a < 3; ++a) s[a] = side * cubes[k][a] + (side - 1) * corner[i][a];
        mapping.pairs.emplace_back(static_cast<Dart>(k) * kVoxelDarts + i,
                                   index.at(s) * kVoxelDarts + i);
      }
  }
};

// Positions of a polycube (on <1,2,3>): the corner of each dart of voxel v is (v + corner) * scale.
inline EmbeddedMap with_positions(const Map& polycube, const std::vector<Voxel>& voxels,
                                  double scale) {
  EmbeddedMap m;
  m.map = polycube;
  m.fields.push_back(EmbeddingField::numeric("position", OrbitType{1, 2, 3}));
  const auto corner = local_corners();
  std::vector<bool> done(polycube.capacity(), false);
  for (size_t k = 0; k < voxels.size(); ++k)
    for (Dart i = 0; i < kVoxelDarts; ++i) {
      const Dart d = static_cast<Dart>(k) * kVoxelDarts + i;
      if (done[d]) continue;
      Vec3 p{};
      for (size_t a = 0; a < 3; ++a) p[a] = (voxels[k][a] + corner[i][a]) * scale;
      m.fields[0].values.set(polycube, d, p);
      for (Dart e : orbit(polycube, OrbitType{1, 2, 3}, d)) done[e] = true;
    }
  return m;
}

}  // namespace gmr::inference::test::polycube
