#include "model/replace/cell_sweep.hpp"

#include <algorithm>

#include "model/core/error.hpp"

namespace gmr::replace {

namespace {

// The met bits of this thread: all clear between sweeps.
std::vector<uint64_t>& met_words(Dart capacity) {
  thread_local std::vector<uint64_t> words;
  const size_t n = (size_t(capacity) + 63) / 64;
  if (words.size() < n) words.resize(n, 0);
  return words;
}

}  // namespace

CellSweep::CellSweep(const Map& g, int cell_dim, const std::vector<Dart>* only)
    : g_(g),
      cell_dim_(cell_dim),
      only_(only),
      capacity_(g.capacity()),
      met_{met_words(g.capacity()).data(), g.capacity()} {
  if (only)
    for (Dart d : *only)
      if (!g.alive(d)) throw Error(ErrorCode::Usage, "no such dart", "dart " + std::to_string(d));
}

CellSweep::~CellSweep() {
  if (only_)
    for (Dart x : listed_) met_.reset(x);
  else
    std::fill(met_.bits, met_.bits + (size_t(capacity_) + 63) / 64, 0);
}

void CellSweep::throw_listed_twice(Dart d) {
  throw Error(ErrorCode::Usage, "a cell is listed twice", "dart " + std::to_string(d));
}

void CellSweep::meet(const Dart* darts, size_t count) {
  if (only_) listed_.insert(listed_.end(), darts, darts + count);
  if (g_.dimension() <= cell_dim_) return;
  const Dart* across = g_.links(cell_dim_ + 1).data();
  for (size_t k = 0; k < count; ++k) {
    const Dart y = across[darts[k]];
    met_.set(y);
    if (only_) listed_.push_back(y);
  }
}

void CellSweep::traverse(Dart d, const std::vector<uint32_t>& flag,
                         const std::vector<uint8_t>& positive, BoundaryGraph& c) {
  cell_boundary(g_, cell_dim_, d, flag, positive, c);
  for (Dart x : c.dart) met_.set(x);
  meet(c.dart.data(), c.dart.size());
}

bool CellSweep::follow(Dart d, const uint32_t* word, uint32_t size,
                       const std::vector<uint32_t>& flag, Dart* out) {
  if (!follow_word(g_, cell_dim_, d, word, size, flag, met_, out)) return false;
  meet(out, size);
  return true;
}

}  // namespace gmr::replace
