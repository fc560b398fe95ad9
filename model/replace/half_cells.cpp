#include "model/replace/half_cells.hpp"

#include <algorithm>
#include <vector>

#include "model/core/buffer_pool.hpp"
#include "model/core/error.hpp"
#include "model/replace/word_traversal.hpp"

namespace gmr::replace {

namespace {

struct Sweep {
  const Dart* link[3];  // alpha_0, alpha_1, alpha_2 (volumes)
  int i;
  Dart cap;
  std::vector<uint64_t> bits;
  MetBits marks;  // over bits
  std::vector<Dart> stack, walked, seeds;
  // With a volume sweep of a 3-G-map: the half-faces of the volumes walked, counted as
  // count_half_cells(g, 2) counts them (faces_exact false once a volume was traversed instead).
  const Dart* across = nullptr;
  size_t faces = 0;
  bool faces_exact = true;

  bool met(Dart x) const { return marks.test(x); }
  void meet(Dart x) { marks.set(x); }

  // Breadth-first over alpha_0..alpha_{i-1} from the darts on the stack (met), for a half-cell
  // with free darts.
  void traverse() {
    while (!stack.empty()) {
      const Dart x = stack.back();
      stack.pop_back();
      for (int j = 0; j < i; ++j) {
        const Dart y = link[j][x];
        if (y < cap && !met(y)) {
          meet(y);
          stack.push_back(y);
        }
      }
    }
  }
  // The cycle of d's half-face, met; false when it meets a free dart (its darts then in walked).
  bool walk_face(Dart d) {
    walked.clear();
    Dart x = d;
    do {
      meet(x);
      walked.push_back(x);
      const Dart y = link[0][x];
      if (y == x || y >= cap) return false;
      meet(y);
      walked.push_back(y);
      x = link[1][y];
      if (x == y || x >= cap) return false;
    } while (x != d);
    return true;
  }
  // The walked half-face of s: one half-cell, two when alpha_3 sends it onto itself (alpha_3
  // commutes with alpha_0 and alpha_1, so it sends the whole <0,1>-orbit onto one; the other
  // half-face, when distinct, is counted when its volume is walked).
  void count_half_face(Dart s) {
    const Dart other = across[s];
    faces += 1 + (other != s && std::find(walked.begin(), walked.end(), other) != walked.end());
  }
  // d's half-cell, met.
  void half_cell(Dart d) {
    if (i == 2) {
      if (walk_face(d)) return;
      stack = walked;
      return traverse();
    }
    // A volume: its half-faces, joined by alpha_2.
    seeds.assign(1, d);
    while (!seeds.empty()) {
      const Dart s = seeds.back();
      seeds.pop_back();
      if (met(s)) continue;
      if (!walk_face(s)) {
        faces_exact = false;
        stack = walked;
        for (Dart x : seeds) stack.push_back(x), meet(x);
        return traverse();
      }
      if (across) count_half_face(s);
      for (Dart x : walked) {
        const Dart z = link[2][x];
        if (z < cap && !met(z)) seeds.push_back(z);
      }
    }
  }
};

// The half-cells of dimension i, counted by sweep s (set up here); with s.across set (a volume
// sweep of a 3-G-map), the half-faces it walks are counted too (s.faces).
size_t sweep_half_cells(const Map& g, int i, Sweep& s) {
  const int n = g.dimension();
  for (int j = 0; j < i; ++j) s.link[j] = g.links(j).data();
  s.i = i;
  s.cap = g.capacity();
  s.bits.assign((size_t(s.cap) + 63) / 64, 0);
  s.marks = {s.bits.data(), s.cap};
  const Dart* across = n > i ? g.links(i + 1).data() : nullptr;
  size_t halves = 0;
  for (Dart d = s.marks.next_clear(0); d < s.cap; d = s.marks.next_clear(d + 1)) {
    if (!g.alive(d)) continue;
    // The cell's other half: a half-cell of its own (met in the sweep), or this one itself.
    const Dart other = across ? across[d] : d;
    const bool other_met = other >= s.cap || s.met(other);
    s.half_cell(d);
    halves += 1 + (other != d && !other_met && other < s.cap && s.met(other));
  }
  return halves;
}

}  // namespace

size_t count_half_cells(const Map& g, int i) {
  const int n = g.dimension();
  if (g.is_omap() || (i != 2 && i != 3) || (n != i && n != i + 1))
    throw Error(ErrorCode::Usage, "half-cells are half-faces or half-volumes of a G-map",
                "i = " + std::to_string(i));
  Sweep s;
  return sweep_half_cells(g, i, s);
}

namespace {

// count_half_faces_and_volumes on a map without deleted darts whose half-faces have no free dart
// (the common case), in one loop with no list of the walked darts: a half-face is walked as its
// cycle, and for each edge (x, alpha_0 x) on it alpha_2(x), if not met yet, is a seed of the same
// volume (alpha_2 alpha_0 = alpha_0 alpha_2: alpha_2(alpha_0 x) lies in the half-face of
// alpha_2(x)). A dart is a seed at most once (from its alpha_2-neighbour's walk), so the seeds fit
// in one array of the map's size. The half-face of s counts twice when alpha_3 sends it onto itself
// and not s onto s: alpha_3(s), not met before the walk, is met by it. False, with h unspecified,
// as soon as a free dart below 2 is met (the general sweep then counts).
bool count_closed_half_faces_and_volumes(const Map& g, HalfFacesAndVolumes& h) {
  if (g.has_holes()) return false;
  const Dart cap = g.capacity();
  const Dart *a0 = g.links(0).data(), *a1 = g.links(1).data(), *a2 = g.links(2).data(),
             *a3 = g.links(3).data();
  const size_t words = (size_t(cap) + 63) / 64;
  ScratchTable<uint64_t> bits;
  bits.reserve(words);
  bits->assign(words, 0);
  ScratchTable<Dart> seeds;
  seeds.resize_for_overwrite(size_t(cap) + 1);
  Dart* const seed = seeds->data();
  const MetBits met{bits->data(), cap};
  size_t faces = 0, volumes = 0;
  for (Dart d = met.next_clear(0); d < cap; d = met.next_clear(d + 1)) {
    ++volumes;
    size_t top = 0;
    seed[top++] = d;
    while (top > 0) {
      const Dart s = seed[--top];
      if (met.test(s)) continue;
      const Dart other = a3[s];
      const bool other_before = other >= cap || met.test(other);
      Dart x = s;
      do {
        const Dart y = a0[x];
        if (y == x || y >= cap) return false;
        met.set(x);
        met.set(y);
        const Dart z = a2[x];
        seed[top] = z;
        top += z < cap && !met.test(z);
        const Dart next = a1[y];
        if (next == y || next >= cap) return false;
        x = next;
      } while (x != s);
      faces += 1 + (other != s && !other_before && met.test(other));
    }
  }
  h = {faces, volumes};
  return true;
}

}  // namespace

HalfFacesAndVolumes count_half_faces_and_volumes(const Map& g) {
  if (g.is_omap() || g.dimension() != 3)
    throw Error(ErrorCode::Usage, "half-faces and half-volumes are counted together in 3-G-maps");
  HalfFacesAndVolumes closed;
  if (count_closed_half_faces_and_volumes(g, closed)) return closed;
  Sweep s;
  s.across = g.links(3).data();
  const size_t volumes = sweep_half_cells(g, 3, s);
  return {s.faces_exact ? s.faces : count_half_cells(g, 2), volumes};
}

}  // namespace gmr::replace
