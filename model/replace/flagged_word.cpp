#include "model/replace/flagged_word.hpp"

#include <algorithm>

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

// Sizes of the orbits of the first m neighbours (all but the last): for a volume boundary
// (alpha_0, alpha_1, alpha_2 or abar_2) the number of darts of each face of the boundary surface.
// Isomorphisms commute with the neighbours, so these sizes are invariants of the darts.
const std::vector<uint32_t>& face_sizes(const BoundaryGraph& b) {
  thread_local std::vector<uint32_t> size, stack;
  size.assign(b.size(), 0);
  if (b.arity == 3) {
    // A face is the orbit of two involutions (neighbours 0 and 1): a cycle, or a path between two
    // fixed points (free darts), walked from k both ways.
    for (uint32_t k = 0; k < b.size(); ++k) {
      if (size[k]) continue;
      stack.assign(1, k);
      size[k] = 1;
      for (int first = 0; first < 2; ++first) {
        uint32_t x = k;
        for (int j = first;; j ^= 1) {
          const uint32_t y = b.neighbour(x, j);
          if (y == x || size[y]) break;  // a path end, or the cycle closed
          size[y] = 1;
          stack.push_back(y);
          x = y;
        }
      }
      for (uint32_t y : stack) size[y] = static_cast<uint32_t>(stack.size());
    }
    return size;
  }
  for (uint32_t k = 0; k < b.size(); ++k) {
    if (size[k]) continue;
    stack.assign(1, k);
    size[k] = 1;  // visited; the final size is written below
    for (size_t i = 0; i < stack.size(); ++i)
      for (int j = 0; j + 1 < b.arity; ++j) {
        const uint32_t y = b.neighbour(stack[i], j);
        if (!size[y]) {
          size[y] = 1;
          stack.push_back(y);
        }
      }
    for (uint32_t y : stack) size[y] = static_cast<uint32_t>(stack.size());
  }
  return size;
}

// The minimal word, one start after the other, each compared on the fly with the best so far
// (early abort): O(|B|) memory, for graphs too large for one label array per start.
CellSignature sequential_minimum(const BoundaryGraph& b, const std::vector<uint32_t>& starts,
                                 bool with_flags) {
  CellSignature s;
  std::vector<uint32_t> label(b.size(), 0), order;
  bool have = false;
  for (uint32_t k : starts) {
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

}  // namespace

Word boundary_word(const BoundaryGraph& b, uint32_t start, bool with_flags) {
  std::vector<uint32_t> label(b.size(), 0), order;
  Word w;
  stream_word(b, start, with_flags, nullptr, label, order, &w);
  return w;
}

void boundary_word(const BoundaryGraph& b, uint32_t start, Word& out) {
  thread_local std::vector<uint32_t> label, order;
  if (label.size() < b.size()) label.resize(b.size(), 0);  // all zero between calls
  stream_word(b, start, true, nullptr, label, order, &out);
}

void boundary_word(const BoundaryGraph& b, uint32_t start, Word& out,
                   std::vector<uint32_t>& order) {
  // The loop of stream_word with the letters written in place: per dart in label order, its flag
  // and the labels of its neighbours (a neighbour labelled when new).
  thread_local std::vector<uint32_t> label;
  const uint32_t n = b.size();
  if (label.size() < n) label.resize(n, 0);  // all zero between calls
  const int m = b.arity;
  const size_t base = out.size();
  out.resize(base + size_t(n) * (m + 1));
  order.resize(n);
  uint32_t* w = out.data() + base;
  uint32_t* o = order.data();
  uint32_t* l = label.data();
  const uint32_t* nbr = b.nbr.data();
  const uint32_t* flag = b.flag.data();
  uint32_t length = 1;
  o[0] = start;
  l[start] = 1;
  for (uint32_t k = 0; k < length; ++k) {
    const uint32_t x = o[k];
    *w++ = flag[x];
    const uint32_t* nx = nbr + size_t(x) * m;
    for (int j = 0; j < m; ++j) {
      const uint32_t y = nx[j];
      if (!l[y]) {
        o[length] = y;
        l[y] = ++length;
      }
      *w++ = l[y];
    }
  }
  for (uint32_t k = 0; k < length; ++k) l[o[k]] = 0;
  out.resize(base + size_t(length) * (m + 1));  // a disconnected graph: the start's component
  order.resize(length);
}

void numbered_boundary_word(const BoundaryGraph& b, Word& out) {
  const uint32_t n = b.size();
  const int m = b.arity;
  const size_t base = out.size();
  out.resize(base + size_t(n) * (m + 1));
  uint32_t* w = out.data() + base;
  const uint32_t* nbr = b.nbr.data();
  for (uint32_t k = 0; k < n; ++k) {
    *w++ = b.flag[k];
    for (int j = 0; j < m; ++j) *w++ = *nbr++ + 1;
  }
}

std::vector<uint32_t> boundary_labeling(const BoundaryGraph& b, uint32_t start) {
  std::vector<uint32_t> label(b.size(), 0), order;
  stream_word(b, start, false, nullptr, label, order, nullptr);
  return order;
}

void boundary_labeling(const BoundaryGraph& b, uint32_t start, std::vector<uint32_t>& order) {
  thread_local std::vector<uint32_t> label;
  if (label.size() < b.size()) label.resize(b.size(), 0);  // all zero between calls
  stream_word(b, start, false, nullptr, label, order, nullptr);
}

// The start darts (Def. 5 with flags): the flagged darts (in D+ in oriented mode) if there are
// some, else every dart (of D+ in oriented mode), in local order. For volume boundaries
// (arity 3) only those whose pair (size of their face, size of the face across their edge) is
// the smallest are kept: the pair is an isomorphism invariant, so the kept set is mapped onto
// itself by every isomorphism, the minimum over it is still a canonical form, and it holds every
// start reaching the minimum (the automorphism count is unchanged).
StartSet start_darts(const BoundaryGraph& b, Mode mode, bool with_flags) {
  std::vector<uint32_t> all, flagged;
  for (uint32_t k = 0; k < b.size(); ++k) {
    if (mode == Mode::Oriented && !b.positive[k]) continue;
    all.push_back(k);
    if (with_flags && b.flag[k] != 0) flagged.push_back(k);
  }
  StartSet s;
  s.darts = std::move(flagged.empty() ? all : flagged);
  if (b.arity < 3 || s.darts.empty()) return s;
  const std::vector<uint32_t>& size = face_sizes(b);
  auto key = [&](uint32_t k) {
    return uint64_t(size[k]) << 32 | size[b.neighbour(k, b.arity - 1)];
  };
  s.invariant = UINT64_MAX;
  for (uint32_t k : s.darts) s.invariant = std::min(s.invariant, key(k));
  std::erase_if(s.darts, [&](uint32_t k) { return key(k) != s.invariant; });
  return s;
}

uint32_t first_start_dart(const BoundaryGraph& b, Mode mode) {
  // start_darts without the lists: the candidates are the flagged darts (of D+) if there are
  // some, else all darts (of D+); for arity 3 the first candidate with the smallest pair.
  const uint32_t n = b.size();
  auto candidate = [&](uint32_t k) { return mode == Mode::Unoriented || b.positive[k]; };
  bool flagged = false;
  for (uint32_t k = 0; k < n && !flagged; ++k) flagged = candidate(k) && b.flag[k] != 0;
  auto in_set = [&](uint32_t k) { return candidate(k) && (!flagged || b.flag[k] != 0); };
  if (b.arity < 3) {
    for (uint32_t k = 0; k < n; ++k)
      if (in_set(k)) return k;
    return UINT32_MAX;
  }
  const std::vector<uint32_t>& size = face_sizes(b);
  uint64_t least = UINT64_MAX;
  uint32_t first = UINT32_MAX;
  for (uint32_t k = 0; k < n; ++k) {
    if (!in_set(k)) continue;
    const uint64_t key = uint64_t(size[k]) << 32 | size[b.neighbour(k, b.arity - 1)];
    if (key < least) {
      least = key;
      first = k;
    }
  }
  return first;
}

constexpr size_t kLockstepLabels = size_t(1) << 22;  // 16 MB of per-start labels at most

// The minimal word over the start darts, all start darts streamed in lockstep (one dart of each
// BFS per round, Def. 5): a start whose next letters exceed the round's smallest is dropped at
// once, so only the starts reaching the minimum (the automorphisms) are traversed to the end and
// no word is streamed twice. Each start has its own label array (all zero between calls).
CellSignature minimal_signature(const BoundaryGraph& b, Mode mode, bool with_flags) {
  return minimal_signature(b, start_darts(b, mode, with_flags), with_flags);
}

CellSignature minimal_signature(const BoundaryGraph& b, const StartSet& start_set,
                                bool with_flags) {
  CellSignature s;
  if (b.size() == 0) return s;
  if (b.size() >= UINT32_MAX / 2) throw Error(ErrorCode::Range, "cell too large for 32-bit labels");
  const std::vector<uint32_t>& starts = start_set.darts;
  const uint32_t n = b.size(), width = static_cast<uint32_t>(b.arity) + (with_flags ? 1 : 0);
  if (double(starts.size()) * n > double(kLockstepLabels))
    return sequential_minimum(b, starts, with_flags);
  thread_local std::vector<uint32_t> label, order, length, alive, next, letters, best;
  const size_t m = starts.size();
  if (label.size() < m * n) label.resize(m * n, 0);
  if (order.size() < m * n) order.resize(m * n);
  length.assign(m, 1);
  alive.resize(m);
  letters.resize(m * width);
  for (uint32_t c = 0; c < m; ++c) {
    alive[c] = c;
    order[size_t(c) * n] = starts[c];
    label[size_t(c) * n + starts[c]] = 1;
  }
  auto drop = [&](uint32_t c) {
    uint32_t* l = &label[size_t(c) * n];
    for (uint32_t k = 0; k < length[c]; ++k) l[order[size_t(c) * n + k]] = 0;
  };
  s.word.reserve(size_t(n) * width + 1);  // + 1: room for a key prefix (pattern_store.hpp)
  for (uint32_t k = 0; k < n && !alive.empty(); ++k) {
    // A word that ends here (disconnected graph) is a proper prefix of the others: smaller.
    bool some_end = false;
    for (uint32_t c : alive) some_end |= length[c] <= k;
    if (some_end) {
      next.clear();
      for (uint32_t c : alive) (length[c] <= k ? next : best).push_back(c);
      for (uint32_t c : best) drop(c);
      best.clear();
      alive.swap(next);
      break;
    }
    // This round's letters of every alive start; keep those equal to the smallest.
    const uint32_t* least = nullptr;
    for (uint32_t c : alive) {
      uint32_t* l = &label[size_t(c) * n];
      uint32_t* o = &order[size_t(c) * n];
      uint32_t* w = &letters[size_t(c) * width];
      const uint32_t x = o[k];
      if (with_flags) *w++ = b.flag[x];
      for (int j = 0; j < b.arity; ++j) {
        const uint32_t y = b.neighbour(x, j);
        if (!l[y]) {
          o[length[c]] = y;
          l[y] = ++length[c];
        }
        *w++ = l[y];
      }
      const uint32_t* mine = &letters[size_t(c) * width];
      if (!least) {
        least = mine;
        continue;
      }
      uint32_t j = 0;
      while (j < width && mine[j] == least[j]) ++j;
      if (j < width && mine[j] < least[j]) least = mine;
    }
    next.clear();
    for (uint32_t c : alive) {
      const uint32_t* mine = &letters[size_t(c) * width];
      uint32_t j = 0;
      while (j < width && mine[j] == least[j]) ++j;
      if (j == width)
        next.push_back(c);
      else
        drop(c);
    }
    s.word.insert(s.word.end(), least, least + width);
    alive.swap(next);
  }
  s.start = starts[alive.front()];
  s.automorphisms = static_cast<uint32_t>(alive.size());
  for (uint32_t c : alive) drop(c);
  return s;
}

size_t WordHash::operator()(const Word& w) const noexcept {
  // Four independent lanes, two letters each per round (multiply-xorshift), so that the
  // multiplications of a round overlap; the lanes and the tail are mixed at the end.
  auto mix = [](uint64_t h, uint64_t v) {
    h = (h ^ v) * 0xbf58476d1ce4e5b9ull;
    return h ^ (h >> 31);
  };
  auto pair = [&](size_t i) { return uint64_t(w[i]) << 32 | w[i + 1]; };
  uint64_t h0 = 0x9e3779b97f4a7c15ull ^ w.size(), h1 = 0x94d049bb133111ebull,
           h2 = 0x2545f4914f6cdd1dull, h3 = 0xd6e8feb86659fd93ull;
  size_t i = 0;
  for (; i + 8 <= w.size(); i += 8) {
    h0 = mix(h0, pair(i));
    h1 = mix(h1, pair(i + 2));
    h2 = mix(h2, pair(i + 4));
    h3 = mix(h3, pair(i + 6));
  }
  for (; i < w.size(); ++i) h0 = mix(h0, w[i]);
  uint64_t h = mix(mix(mix(h0, h1), h2), h3);
  h *= 0x94d049bb133111ebull;
  return static_cast<size_t>(h ^ (h >> 29));
}

}  // namespace gmr::replace
