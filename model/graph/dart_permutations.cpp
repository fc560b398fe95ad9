#include "model/graph/dart_permutations.hpp"

#include <algorithm>
#include <functional>

namespace gmr::graph {

std::vector<DartPermutation> involutions(size_t k) {
  std::vector<DartPermutation> out;
  DartPermutation p(k, kNoDart);
  std::function<void()> rec = [&] {
    size_t x = 0;
    while (x < k && p[x] != kNoDart) ++x;
    if (x == k) {
      out.push_back(p);
      return;
    }
    p[x] = static_cast<Dart>(x);
    rec();
    for (size_t y = x + 1; y < k; ++y) {
      if (p[y] != kNoDart) continue;
      p[x] = static_cast<Dart>(y);
      p[y] = static_cast<Dart>(x);
      rec();
      p[y] = kNoDart;
    }
    p[x] = kNoDart;
  };
  rec();
  return out;
}

std::vector<DartPermutation> permutations(size_t k) {
  std::vector<DartPermutation> out;
  DartPermutation p(k);
  for (size_t x = 0; x < k; ++x) p[x] = static_cast<Dart>(x);
  do out.push_back(p);
  while (std::next_permutation(p.begin(), p.end()));
  return out;
}

bool commute(const DartPermutation& a, const DartPermutation& b) {
  for (size_t x = 0; x < a.size(); ++x)
    if (b[a[b[a[x]]]] != x) return false;
  return true;
}

bool connected(const std::vector<const DartPermutation*>& s, size_t k) {
  std::vector<bool> seen(k, false);
  std::vector<Dart> stack{0};
  seen[0] = true;
  size_t count = 1;
  while (!stack.empty()) {
    const Dart d = stack.back();
    stack.pop_back();
    for (const DartPermutation* p : s) {
      const Dart e = (*p)[d];
      if (!seen[e]) {
        seen[e] = true;
        ++count;
        stack.push_back(e);
      }
    }
  }
  return count == k;
}

}  // namespace gmr::graph
