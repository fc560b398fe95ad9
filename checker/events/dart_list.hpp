// The orbits named on one side of an event (orbit_event.hpp): a short list of darts. Almost every
// event names one or two orbits on each side, so up to two darts are kept inline and only longer
// lists (a split or a merge of three orbits or more) allocate: logging the events of a local rule
// application then costs no allocation per event side (docs/events.md, "Run time").
#pragma once
#include <algorithm>
#include <compare>
#include <cstdint>
#include <initializer_list>
#include <vector>

#include "model/core/map.hpp"

namespace gmr::events {

class DartList {
 public:
  using value_type = Dart;
  using iterator = Dart*;
  using const_iterator = const Dart*;

  DartList() = default;
  DartList(std::initializer_list<Dart> ds) { append(ds.begin(), ds.end()); }
  DartList(const std::vector<Dart>& ds) {
    append(ds.begin(), ds.end());
  }  // NOLINT: implicit, as a vector
  DartList(const DartList& o) { append(o.begin(), o.end()); }
  DartList(DartList&& o) noexcept : size_(o.size_), heap_(std::move(o.heap_)) {
    std::copy(o.small_, o.small_ + kInline, small_);
    o.size_ = 0;
    o.heap_.clear();
  }
  DartList& operator=(const DartList& o) {
    if (this != &o) {
      clear();
      append(o.begin(), o.end());
    }
    return *this;
  }
  DartList& operator=(DartList&& o) noexcept {
    if (this != &o) {
      size_ = o.size_;
      heap_ = std::move(o.heap_);
      std::copy(o.small_, o.small_ + kInline, small_);
      o.size_ = 0;
      o.heap_.clear();
    }
    return *this;
  }

  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  Dart* begin() { return data(); }
  Dart* end() { return data() + size_; }
  const Dart* begin() const { return data(); }
  const Dart* end() const { return data() + size_; }
  Dart& operator[](size_t k) { return data()[k]; }
  Dart operator[](size_t k) const { return data()[k]; }
  Dart front() const { return data()[0]; }
  Dart back() const { return data()[size_ - 1]; }
  std::vector<Dart> vector() const { return {begin(), end()}; }

  void push_back(Dart d) {
    if (heap_.empty() && size_ < kInline) {
      small_[size_++] = d;
      return;
    }
    if (heap_.empty()) heap_.assign(small_, small_ + size_);
    heap_.push_back(d);
    ++size_;
  }
  void clear() {
    size_ = 0;
    heap_.clear();
  }

  friend bool operator==(const DartList& a, const DartList& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end());
  }
  friend std::strong_ordering operator<=>(const DartList& a, const DartList& b) {
    return std::lexicographical_compare_three_way(a.begin(), a.end(), b.begin(), b.end());
  }

 private:
  static constexpr uint32_t kInline = 2;
  template <class It>
  void append(It b, It e) {
    for (; b != e; ++b) push_back(*b);
  }
  Dart* data() { return heap_.empty() ? small_ : heap_.data(); }
  const Dart* data() const { return heap_.empty() ? small_ : heap_.data(); }

  uint32_t size_ = 0;
  Dart small_[kInline] = {};
  std::vector<Dart> heap_;  // all the darts, once there are more than kInline
};

}  // namespace gmr::events
