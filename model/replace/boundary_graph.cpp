#include "model/replace/boundary_graph.hpp"

#include <algorithm>

#include "model/core/error.hpp"
#include "model/core/huge_pages.hpp"
#include "model/core/orbit.hpp"

namespace gmr::replace {

Dart boundary_successor(const Map& g, int i, Dart d) {
  Dart x = g.alpha(i, d);
  for (size_t steps = 0; !g.is_free(i + 1, x); ++steps) {
    if (steps > g.capacity())
      throw Error(ErrorCode::InvalidMap, "no boundary successor (the fan does not close)",
                  "dart " + std::to_string(d));
    x = g.alpha(i, g.alpha(i + 1, x));
  }
  return x;
}

namespace {

// Fills nbr from a local index and a per-dart neighbour function. The dart -> local index table
// is a per-thread array indexed by dart, reset after use (no hashing, no per-cell allocation).
// The dart -> local index table of this thread: UINT32_MAX everywhere between uses.
std::vector<uint32_t>& local_index(Dart capacity) {
  thread_local std::vector<uint32_t> local;
  resize_in_huge_pages(local, capacity, UINT32_MAX);
  return local;
}

template <class Nbr>
void fill(BoundaryGraph& b, Dart capacity, const std::vector<uint32_t>& flag,
          const std::vector<uint8_t>& positive, Nbr nbr) {
  std::vector<uint32_t>& local = local_index(capacity);
  for (uint32_t k = 0; k < b.size(); ++k) local[b.dart[k]] = k;
  struct Reset {
    std::vector<uint32_t>& local;
    const std::vector<Dart>& darts;
    ~Reset() {
      for (Dart d : darts) local[d] = UINT32_MAX;
    }
  } reset{local, b.dart};
  b.nbr.resize(size_t(b.size()) * b.arity);
  b.flag.resize(b.size());
  b.positive.resize(b.size());
  for (uint32_t k = 0; k < b.size(); ++k) {
    const Dart d = b.dart[k];
    b.flag[k] = d < flag.size() ? flag[d] : 0;
    b.positive[k] = positive.empty() ? 1 : positive[d];
    for (int j = 0; j < b.arity; ++j) {
      const Dart y = nbr(d, j);
      if (y >= capacity || local[y] == UINT32_MAX)
        throw Error(ErrorCode::InvalidMap, "boundary neighbour outside the boundary",
                    "dart " + std::to_string(d));
      b.nbr[size_t(k) * b.arity + j] = local[y];
    }
  }
}

}  // namespace

BoundaryGraph cell_boundary(const Map& g, int i, Dart d, const std::vector<uint32_t>& flag,
                            const std::vector<uint8_t>& positive) {
  BoundaryGraph b;
  b.dart.reserve(256);
  b.nbr.reserve(size_t(256) * i);
  cell_boundary(g, i, d, flag, positive, b);
  return b;
}

void cell_boundary(const Map& g, int i, Dart d, const std::vector<uint32_t>& flag,
                   const std::vector<uint8_t>& positive, BoundaryGraph& b) {
  std::vector<uint32_t>& local = local_index(g.capacity());
  cell_boundary(g, i, d, flag, positive, local, b);
  for (Dart x : b.dart) local[x] = UINT32_MAX;
}

void cell_boundary(const Map& g, int i, Dart d, const std::vector<uint32_t>& flag,
                   const std::vector<uint8_t>& positive, std::vector<uint32_t>& local,
                   BoundaryGraph& b) {
  if (!g.alive(d)) throw Error(ErrorCode::Range, "no such dart", "dart " + std::to_string(d));
  if (g.is_omap() || i < 1 || i > g.dimension() + 1)
    throw Error(ErrorCode::Usage, "the <0..i-1>-orbit of a G-map, 1 <= i <= n + 1",
                "i = " + std::to_string(i));
  // One breadth-first traversal of the <0..i-1>-orbit (neighbours by increasing dimension, the
  // order of orbit()) numbers the darts and records their neighbours; then their flags and
  // classes. The arrays are written in place (grown when a cell outgrows them).
  b.arity = i;
  const Dart* link[kMaxDim];
  for (int j = 0; j < i; ++j) link[j] = g.links(j).data();
  uint32_t* l = local.data();
  size_t room = std::max<size_t>(b.dart.capacity(), 64);
  b.dart.resize(room);
  b.nbr.resize(room * i);
  Dart* dart = b.dart.data();
  uint32_t* nbr = b.nbr.data();
  uint32_t count = 1;
  dart[0] = d;
  l[d] = 0;
  for (uint32_t k = 0; k < count; ++k) {
    const Dart x = dart[k];
    for (int j = 0; j < i; ++j) {
      const Dart y = link[j][x];
      uint32_t ly = l[y];
      if (ly == UINT32_MAX) {
        if (count == room) {
          room *= 2;
          b.dart.resize(room);
          b.nbr.resize(room * i);
          dart = b.dart.data();
          nbr = b.nbr.data();
        }
        ly = count++;
        l[y] = ly;
        dart[ly] = y;
        // y is read later in breadth-first order: its links and flag are fetched meanwhile.
        for (int p = 0; p < i; ++p) __builtin_prefetch(link[p] + y);
        if (y < flag.size()) __builtin_prefetch(flag.data() + y);
      }
      nbr[size_t(k) * i + j] = ly;
    }
  }
  b.dart.resize(count);
  b.nbr.resize(size_t(count) * i);
  b.flag.resize(count);
  for (uint32_t k = 0; k < count; ++k) b.flag[k] = dart[k] < flag.size() ? flag[dart[k]] : 0;
  if (positive.empty()) {
    b.positive.assign(count, 1);
  } else {
    b.positive.resize(count);
    for (uint32_t k = 0; k < count; ++k) b.positive[k] = positive[dart[k]];
  }
}

BoundaryGraph pattern_boundary(const Map& p, const std::vector<uint32_t>& flag,
                               const std::vector<uint8_t>& positive) {
  const int n = p.dimension();
  BoundaryGraph b;
  b.arity = n;
  p.for_each_dart([&](Dart d) {
    if (p.is_free(n, d)) b.dart.push_back(d);
  });
  fill(b, p.capacity(), flag, positive,
       [&](Dart x, int j) { return j < n - 1 ? p.alpha(j, x) : boundary_successor(p, n - 1, x); });
  return b;
}

bool is_connected(const BoundaryGraph& b) {
  if (b.size() == 0) return true;
  std::vector<uint8_t> seen(b.size(), 0);
  std::vector<uint32_t> stack{0};
  seen[0] = 1;
  uint32_t count = 1;
  while (!stack.empty()) {
    const uint32_t k = stack.back();
    stack.pop_back();
    for (int j = 0; j < b.arity; ++j) {
      const uint32_t y = b.neighbour(k, j);
      if (!seen[y]) {
        seen[y] = 1;
        ++count;
        stack.push_back(y);
      }
    }
  }
  return count == b.size();
}

}  // namespace gmr::replace
