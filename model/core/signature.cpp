#include "model/core/signature.hpp"

#include <algorithm>

#include "model/core/orbit.hpp"
#include "model/core/word_comparison.hpp"

namespace gmr {

std::string Signature::str() const {
  std::string s = std::string(to_string(kind)) + std::to_string(n) + ":";
  for (const Word& w : components) {
    s += "[";
    for (size_t k = 0; k < w.size(); ++k) s += (k ? "," : "") + std::to_string(w[k]);
    s += "]";
  }
  return s;
}

namespace {

// Streams W(M,d) and compares it on the fly with `best` (when given): returns -1 (smaller),
// 0 (equal), +1 (greater, stopped early). `label` is scratch space indexed by dart, all zero on
// entry and on exit.
int stream_word(const Map& g, Dart d, const std::vector<uint32_t>* flags, const Word* best,
                std::vector<uint32_t>& label, std::vector<Dart>& order, Word* out) {
  const int lo = g.lowest_dim(), n = g.dimension();
  order.clear();
  order.push_back(d);
  label[d] = 1;
  WordComparison word(best, out);
  for (size_t k = 0; k < order.size() && word.so_far() <= 0; ++k) {
    const Dart v = order[k];
    for (int i = lo; i <= n; ++i) {
      const Dart w = g.alpha(i, v);
      if (!label[w]) {
        order.push_back(w);
        label[w] = static_cast<uint32_t>(order.size());
      }
      word.emit(label[w]);
    }
  }
  if (flags && word.so_far() <= 0)
    for (size_t k = 0; k < order.size(); ++k) word.emit((*flags)[order[k]]);
  const int cmp = word.result();
  for (Dart v : order) label[v] = 0;
  return cmp;
}

}  // namespace

std::vector<Dart> bfs_labeling(const Map& g, Dart d) {
  std::vector<uint32_t> label(g.capacity(), 0);
  std::vector<Dart> order;
  stream_word(g, d, nullptr, nullptr, label, order, nullptr);
  return order;
}

Word bfs_word(const Map& g, Dart d, const std::vector<uint32_t>* flags) {
  std::vector<uint32_t> label(g.capacity(), 0);
  std::vector<Dart> order;
  Word w;
  stream_word(g, d, flags, nullptr, label, order, &w);
  return w;
}

Word component_signature(const Map& g, Dart d, const std::vector<uint32_t>* flags) {
  std::vector<uint32_t> label(g.capacity(), 0);
  std::vector<Dart> order;
  const std::vector<Dart> comp = bfs_labeling(g, d);
  Word best;
  stream_word(g, comp[0], flags, nullptr, label, order, &best);
  for (size_t k = 1; k < comp.size(); ++k) {
    Word cand;
    if (stream_word(g, comp[k], flags, &best, label, order, &cand) < 0) {
      cand.clear();
      stream_word(g, comp[k], flags, nullptr, label, order, &cand);
      best = std::move(cand);
    }
  }
  return best;
}

Signature signature(const Map& g, const std::vector<uint32_t>* flags) {
  Signature s;
  s.n = g.dimension();
  s.kind = g.kind();
  for (Dart rep : orbit_representatives(g, OrbitType::range(g.lowest_dim(), g.dimension())))
    s.components.push_back(component_signature(g, rep, flags));
  std::sort(s.components.begin(), s.components.end());
  return s;
}

bool is_isomorphic(const Map& g, const Map& h, const std::vector<uint32_t>* flags_g,
                   const std::vector<uint32_t>* flags_h) {
  if (g.kind() != h.kind() || g.dimension() != h.dimension() || g.size() != h.size()) return false;
  if ((flags_g == nullptr) != (flags_h == nullptr)) return false;
  if (g.size() == 0) return true;
  if (count_components(g) != 1 || count_components(h) != 1)
    return signature(g, flags_g) == signature(h, flags_h);
  const Word ref = bfs_word(g, g.darts().front(), flags_g);
  std::vector<uint32_t> label(h.capacity(), 0);
  std::vector<Dart> order;
  bool found = false;
  h.for_each_dart([&](Dart d) {
    if (!found && stream_word(h, d, flags_h, &ref, label, order, nullptr) == 0) found = true;
  });
  return found;
}

}  // namespace gmr
