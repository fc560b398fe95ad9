#include "model/replace/stride_prefetch.hpp"

namespace gmr::replace {

void prefetch_predicted_cell(const Map& g, int i, const std::vector<uint32_t>& flag, const Dart* last,
                             const Dart* before, uint32_t size) {
  const Dart* link[kMaxDim];
  for (int j = 0; j < i; ++j) link[j] = g.links(j).data();
  const Dart capacity = g.capacity(), flagged = static_cast<Dart>(flag.size());
  // Every second label: the darts of a cell come in runs (a dart and its alpha_0 neighbour are
  // usually numbered next to each other), so this covers its cache lines at half the fetches.
  for (uint32_t k = 0; k < size; k += 2) {
    const Dart next = 2 * last[k] - before[k];  // below 0: wraps past the capacity, skipped
    if (next >= capacity) continue;
    for (int j = 0; j < i; ++j) __builtin_prefetch(link[j] + next);
    if (next < flagged) __builtin_prefetch(flag.data() + next);
  }
}

}  // namespace gmr::replace
