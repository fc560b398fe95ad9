#include "model/replace/flagged_word.hpp"

#include "model/core/error.hpp"
#include "model/core/word_comparison.hpp"

namespace gmr::replace {

const char* to_string(Mode m) { return m == Mode::Oriented ? "oriented" : "unoriented"; }

namespace {

// Streams W(B, s), comparing it on the fly with `best` (when given): -1 smaller, 0 equal, +1
// greater (stopped early). `label` is all zero on entry and on exit.
int stream_word(const BoundaryGraph& b, uint32_t start, bool with_flags, const Word* best,
                std::vector<uint32_t>& label, std::vector<uint32_t>& order, Word* out) {
  order.clear();
  order.push_back(start);
  label[start] = 1;
  WordComparison word(best, out);
  for (size_t k = 0; k < order.size() && (word.so_far() == 0 || out); ++k) {
    const uint32_t x = order[k];
    if (with_flags) word.emit(b.flag[x]);
    for (int j = 0; j < b.arity; ++j) {
      const uint32_t y = b.neighbour(x, j);
      if (!label[y]) {
        order.push_back(y);
        label[y] = static_cast<uint32_t>(order.size());
      }
      word.emit(label[y]);
    }
  }
  const int cmp = word.result();
  for (uint32_t v : order) label[v] = 0;
  return cmp;
}

}  // namespace

Word boundary_word(const BoundaryGraph& b, uint32_t start, bool with_flags) {
  std::vector<uint32_t> label(b.size(), 0), order;
  Word w;
  stream_word(b, start, with_flags, nullptr, label, order, &w);
  return w;
}

std::vector<uint32_t> boundary_labeling(const BoundaryGraph& b, uint32_t start) {
  std::vector<uint32_t> label(b.size(), 0), order;
  stream_word(b, start, false, nullptr, label, order, nullptr);
  return order;
}

CellSignature minimal_signature(const BoundaryGraph& b, Mode mode, bool with_flags) {
  CellSignature s;
  if (b.size() == 0) return s;
  if (b.size() >= UINT32_MAX / 2) throw Error(ErrorCode::Range, "cell too large for 32-bit labels");
  bool any_flag = false;
  if (with_flags)
    for (uint32_t f : b.flag) any_flag |= f != 0;
  auto is_start = [&](uint32_t k, bool flagged_only) {
    if (mode == Mode::Oriented && !b.positive[k]) return false;
    return !flagged_only || b.flag[k] != 0;
  };
  // Flagged starts in D+ if there are some, else every start of the mode.
  bool flagged_only = false;
  if (any_flag)
    for (uint32_t k = 0; k < b.size() && !flagged_only; ++k) flagged_only = is_start(k, true);
  std::vector<uint32_t> label(b.size(), 0), order;
  bool have = false;
  for (uint32_t k = 0; k < b.size(); ++k) {
    if (!is_start(k, flagged_only)) continue;
    if (!have) {
      stream_word(b, k, with_flags, nullptr, label, order, &s.word);
      s.start = k;
      s.automorphisms = 1;
      have = true;
      continue;
    }
    const int cmp = stream_word(b, k, with_flags, &s.word, label, order, nullptr);
    if (cmp == 0) {
      ++s.automorphisms;
    } else if (cmp < 0) {
      s.word.clear();
      stream_word(b, k, with_flags, nullptr, label, order, &s.word);
      s.start = k;
      s.automorphisms = 1;
    }
  }
  return s;
}

size_t WordHash::operator()(const Word& w) const noexcept {
  uint64_t h = 1469598103934665603ull ^ w.size();  // FNV-1a over the entries
  for (uint32_t x : w) {
    h ^= x;
    h *= 1099511628211ull;
  }
  return static_cast<size_t>(h ^ (h >> 29));
}

}  // namespace gmr::replace
