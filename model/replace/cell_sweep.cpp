#include "model/replace/cell_sweep.hpp"

#include <algorithm>

#include "model/core/error.hpp"

namespace gmr::replace {

namespace {

// local[x]: x's index in its cell's boundary graph, UINT32_MAX for the darts of cells not met yet,
// kOtherHalf for the second half-face of a face of a 3-G-map. UINT32_MAX everywhere between
// sweeps.
constexpr uint32_t kOtherHalf = UINT32_MAX - 1;

std::vector<uint32_t>& local_index() {
  thread_local std::vector<uint32_t> local;
  return local;
}

}  // namespace

CellSweep::CellSweep(const Map& g, int cell_dim, const std::vector<Dart>* only)
    : g_(g), cell_dim_(cell_dim), only_(only), capacity_(g.capacity()), local_(local_index()) {
  if (only)
    for (Dart d : *only)
      if (!g.alive(d)) throw Error(ErrorCode::Usage, "no such dart", "dart " + std::to_string(d));
  if (local_.size() < capacity_) local_.resize(capacity_, UINT32_MAX);
}

CellSweep::~CellSweep() {
  if (only_)
    for (Dart x : met_) local_[x] = UINT32_MAX;
  else
    std::fill(local_.begin(), local_.begin() + capacity_, UINT32_MAX);
}

void CellSweep::throw_listed_twice(Dart d) {
  throw Error(ErrorCode::Usage, "a cell is listed twice", "dart " + std::to_string(d));
}

void CellSweep::traverse(Dart d, const std::vector<uint32_t>& flag, const std::vector<uint8_t>& positive,
                         BoundaryGraph& c) {
  cell_boundary(g_, cell_dim_, d, flag, positive, local_, c);
  if (g_.dimension() > cell_dim_)
    for (Dart x : c.dart) {
      const Dart y = g_.alpha(cell_dim_ + 1, x);
      if (local_[y] == UINT32_MAX) local_[y] = kOtherHalf;
      if (only_) met_.push_back(y);
    }
  if (only_) met_.insert(met_.end(), c.dart.begin(), c.dart.end());
}

}  // namespace gmr::replace
