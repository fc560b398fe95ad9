#include "model/replace/direct_hex_subdivision.hpp"

#include "model/core/error.hpp"
#include "model/core/huge_pages.hpp"
#include "model/core/orbit.hpp"

namespace gmr::replace {

namespace {

// Every volume a combinatorial hexahedron: no free dart below 3, quadrangular faces and three
// edges at every corner of every volume.
void require_hexahedra(const Map& g) {
  if (g.is_omap() || g.dimension() != 3)
    throw Error(ErrorCode::InvalidMap, "hexahedral subdivision works on 3-G-maps");
  g.for_each_dart([&](Dart d) {
    for (int i = 0; i < 3; ++i)
      if (g.is_free(i, d))
        throw Error(ErrorCode::InvalidMap,
                    "not a hexahedral mesh: an " + std::to_string(i) + "-free dart",
                    "dart " + std::to_string(d));
    auto r10 = [&](Dart x) { return g.alpha(1, g.alpha(0, x)); };
    auto r21 = [&](Dart x) { return g.alpha(2, g.alpha(1, x)); };
    const bool quad = r10(r10(d)) != d && r10(r10(r10(r10(d)))) == d;
    const bool corner = r21(d) != d && r21(r21(r21(d))) == d;
    if (!quad || !corner)
      throw Error(ErrorCode::InvalidMap,
                  std::string("not a hexahedral mesh: ") +
                      (quad ? "a corner without 3 edges" : "a face that is not a quadrangle"),
                  "dart " + std::to_string(d));
  });
}

Vec3 mean(const Vec3& a, const Vec3& b) {
  return {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
}

// Per dart: the centre of its face and of its volume (averages over the orbits' darts, each
// vertex counted equally often).
void centres(const Map& g, const std::vector<Vec3>& p, std::vector<Vec3>& face,
             std::vector<Vec3>& cell) {
  face.assign(g.capacity(), Vec3{0, 0, 0});
  cell.assign(g.capacity(), Vec3{0, 0, 0});
  std::vector<uint8_t> done(g.capacity(), 0);
  g.for_each_dart([&](Dart d) {
    if (done[d] & 1) return;
    Vec3 c{0, 0, 0};
    Dart x = d;
    for (int k = 0; k < 8; ++k, x = g.alpha(k % 2, x))
      for (int i = 0; i < 3; ++i) c[i] += p[x][i] / 8;
    x = d;
    for (int k = 0; k < 8; ++k, x = g.alpha(k % 2, x)) {
      face[x] = c;
      done[x] |= 1;
    }
  });
  for (Dart d = 0; d < g.capacity(); ++d) {
    if (!g.alive(d) || (done[d] & 2)) continue;
    const std::vector<Dart> volume = orbit(g, OrbitType::range(0, 2), d);
    Vec3 c{0, 0, 0};
    for (Dart x : volume)
      for (int i = 0; i < 3; ++i) c[i] += p[x][i] / double(volume.size());
    for (Dart x : volume) {
      cell[x] = c;
      done[x] |= 2;
    }
  }
}

constexpr uint32_t swap01(uint32_t w) { return (w & 4) | (w & 1) << 1 | (w >> 1 & 1); }
constexpr uint32_t swap12(uint32_t w) { return (w & 1) | (w & 2) << 1 | (w >> 1 & 2); }

}  // namespace

FlaggedMap subdivide_hexahedra(const FlaggedMap& m) {
  const Map& g = m.map;
  require_hexahedra(g);
  std::vector<Dart> index(g.capacity(), kNoDart);
  Dart n = 0;
  g.for_each_dart([&](Dart d) { index[d] = n++; });
  FlaggedMap r{Map(3), {}, {}};
  Map& h = r.map;
  h.add_darts(size_t(n) * 8);
  g.for_each_dart([&](Dart d) {
    const Dart base = index[d] * 8, a1 = index[g.alpha(1, d)] * 8, a2 = index[g.alpha(2, d)] * 8;
    const Dart a3 = index[g.alpha(3, d)] * 8;
    const Dart across = index[g.alpha(2, g.alpha(1, g.alpha(0, g.alpha(1, g.alpha(2, d)))))] * 8;
    for (uint32_t w = 0; w < 8; ++w) {
      h.set_alpha(0, base + w, base + (w ^ 1));
      h.set_alpha(1, base + w, a1 + swap01(w));
      h.set_alpha(2, base + w, a2 + swap12(w));
      h.set_alpha(3, base + w, (w & 4 ? across : a3) + w);
    }
  });
  // Flags and positions in huge pages, as query-replace grows them (FlaggedMap::grow_flags).
  reserve_in_huge_pages(r.flag, h.capacity());
  r.flag.assign(h.capacity(), 1);
  if (m.positioned()) {
    const std::vector<Vec3>& p = m.position;
    std::vector<Vec3> face, cell;
    centres(g, p, face, cell);
    reserve_in_huge_pages(r.position, h.capacity());
    r.position.resize(h.capacity());
    g.for_each_dart([&](Dart d) {
      const Dart e1 = g.alpha(1, d), e3 = g.alpha(1, g.alpha(2, d));
      Vec3* out = &r.position[size_t(index[d]) * 8];
      out[0] = p[d];
      out[1] = mean(p[d], p[g.alpha(0, d)]);
      out[2] = mean(p[e1], p[g.alpha(0, e1)]);
      out[4] = mean(p[e3], p[g.alpha(0, e3)]);
      out[3] = face[d];
      out[5] = face[g.alpha(2, d)];
      out[6] = face[g.alpha(2, e1)];
      out[7] = cell[d];
    });
  }
  return r;
}

}  // namespace gmr::replace
