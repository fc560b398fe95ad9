#include "model/replace/stride_prefetch.hpp"

namespace gmr::replace {

namespace {

// For a fixed arity I: every second label (the darts of a cell come in runs: a dart and its
// alpha_0 neighbour are usually numbered next to each other, so this covers its cache lines at
// half the fetches; fetching at every label, a dart skipped when in the same 16 as the one before,
// was measured slower: the fetches crowd the memory accesses of the replacement).
template <int I>
void prefetch_predicted(const Dart* const* link, const uint32_t* flag, Dart flagged, Dart capacity,
                        const Dart* last, const Dart* before, uint32_t size) {
  for (uint32_t k = 0; k < size; k += 2) {
    const Dart next = 2 * last[k] - before[k];  // below 0: wraps past the capacity, skipped
    if (next >= capacity) continue;
    for (int j = 0; j < I; ++j) __builtin_prefetch(link[j] + next);
    if (next < flagged) __builtin_prefetch(flag + next);
  }
}

}  // namespace

void prefetch_predicted_cell(const Map& g, int i, const std::vector<uint32_t>& flag,
                             const Dart* last, const Dart* before, uint32_t size) {
  const Dart* link[kMaxDim];
  for (int j = 0; j < i; ++j) link[j] = g.links(j).data();
  const Dart capacity = g.capacity(), flagged = static_cast<Dart>(flag.size());
  if (i == 3) prefetch_predicted<3>(link, flag.data(), flagged, capacity, last, before, size);
  if (i == 2) prefetch_predicted<2>(link, flag.data(), flagged, capacity, last, before, size);
}

}  // namespace gmr::replace
