// Dart -> index maps for orbits (used by instantiation and the scheme engine).
//
// A dense array indexed by dart when the orbit covers a good part of the map (fast, O(capacity)
// memory), a hash map otherwise (O(orbit) memory), so that building the map stays linear in the
// orbit for small orbits of huge maps.
#pragma once
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "model/core/map.hpp"

namespace gmr {

class DartIndex {
 public:
  static constexpr uint32_t kNone = UINT32_MAX;
  DartIndex(size_t capacity, size_t expected) {
    dense_ = expected * 8 >= capacity;
    if (dense_)
      dense_map_.assign(capacity, kNone);
    else
      sparse_.reserve(expected * 2);
  }
  void set(Dart d, uint32_t i) {
    if (dense_)
      dense_map_[d] = i;
    else
      sparse_[d] = i;
  }
  uint32_t get(Dart d) const {
    if (dense_) return d < dense_map_.size() ? dense_map_[d] : kNone;
    auto it = sparse_.find(d);
    return it == sparse_.end() ? kNone : it->second;
  }

 private:
  bool dense_ = false;
  std::vector<uint32_t> dense_map_;
  std::unordered_map<Dart, uint32_t> sparse_;
};

}  // namespace gmr
