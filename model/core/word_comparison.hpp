// A word written letter by letter and compared on the fly, lexicographically, with the best word
// found so far: the inner loop of minimal BFS-word signatures (Damiand & Nivoliers Def. 5), which
// stop a start dart's traversal as soon as its word is known to be greater.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace gmr {

class WordComparison {
 public:
  // `best` may be null (nothing to compare with); `out` (may be null) receives every letter.
  WordComparison(const std::vector<uint32_t>* best, std::vector<uint32_t>* out)
      : best_(best), out_(out) {}

  void emit(uint32_t x) {
    if (out_) out_->push_back(x);
    if (best_ && cmp_ == 0) {
      if (pos_ >= best_->size())
        cmp_ = 1;
      else if (x != (*best_)[pos_])
        cmp_ = x < (*best_)[pos_] ? -1 : 1;
    }
    ++pos_;
  }
  // -1 smaller, +1 greater, 0 equal so far.
  int so_far() const { return cmp_; }
  // The verdict once the word is complete: a proper prefix of `best` is smaller.
  int result() const { return best_ && cmp_ == 0 && pos_ < best_->size() ? -1 : cmp_; }

 private:
  const std::vector<uint32_t>* best_;
  std::vector<uint32_t>* out_;
  size_t pos_ = 0;
  int cmp_ = 0;
};

}  // namespace gmr
