#include "model/replace/word_traversal.hpp"

namespace gmr::replace {

namespace {

// follow_word for a fixed arity I (the cell dimension): the loops over the neighbours unrolled.
// AllFlagged: every dart of `met` has a flag (no bound check per dart).
template <int I, bool AllFlagged>
bool follow(const Dart* const* link, Dart d, const uint32_t* w, uint32_t size, const uint32_t* fl,
            Dart flagged, MetBits met, Dart* out) {
  uint32_t count = 1;
  out[0] = d;
  met.set(d);
  for (uint32_t k = 0; k < count; ++k) {
    const Dart x = out[k];
    if ((AllFlagged || x < flagged ? fl[x] : 0) != *w++) goto disagree;
    for (int j = 0; j < I; ++j) {
      const Dart y = link[j][x];
      const uint32_t l = *w++;
      if (l == count + 1) {
        // A new label: y must not be numbered yet (nor met in an earlier cell).
        if (count == size || y >= met.size || met.test(y)) goto disagree;
        met.set(y);
        out[count++] = y;
        // y is read later in label order: its links and flag are fetched meanwhile.
        for (int p = 0; p < I; ++p) __builtin_prefetch(link[p] + y);
        if (AllFlagged || y < flagged) __builtin_prefetch(fl + y);
      } else if (l == 0 || l > count || out[l - 1] != y) {
        goto disagree;
      }
    }
  }
  if (count == size) return true;
disagree:
  for (uint32_t k = 0; k < count; ++k) met.reset(out[k]);
  return false;
}

}  // namespace

bool follow_word(const Map& g, int i, Dart d, const uint32_t* word, uint32_t size,
                 const std::vector<uint32_t>& flag, MetBits met, Dart* out) {
  if (size == 0) return false;
  const Dart* link[kMaxDim];
  for (int j = 0; j < i; ++j) link[j] = g.links(j).data();
  const Dart flagged = static_cast<Dart>(flag.size());
  const bool all = flagged >= met.size;  // as query-replace sizes the flags (begin_replacement)
  switch (i) {
    case 2:
      return all ? follow<2, true>(link, d, word, size, flag.data(), flagged, met, out)
                 : follow<2, false>(link, d, word, size, flag.data(), flagged, met, out);
    case 3:
      return all ? follow<3, true>(link, d, word, size, flag.data(), flagged, met, out)
                 : follow<3, false>(link, d, word, size, flag.data(), flagged, met, out);
    default:
      return false;  // cells are faces or volumes (begin_replacement)
  }
}

}  // namespace gmr::replace
