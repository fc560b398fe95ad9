// Strong indices: a Handle<Tag> is a uint32_t index into one kind of table (the nodes of a
// D-graph, its arcs, ...). Handles of different tags, and handles and integers, do not convert
// into one another implicitly, so that passing an index of one table for another does not
// compile; the conversions at the boundaries are explicit (the constructor, index()).
// A handle is a trivially copyable 4-byte value: it costs what the integer costs.
#pragma once
#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iterator>
#include <ostream>
#include <vector>

namespace gmr {

template <class Tag>
class Handle {
 public:
  constexpr Handle() = default;
  constexpr explicit Handle(uint32_t index) : index_(index) {}

  // The sentinel "no element" (index UINT32_MAX).
  static constexpr Handle none() { return Handle(UINT32_MAX); }

  constexpr uint32_t index() const { return index_; }

  constexpr Handle& operator++() {
    ++index_;
    return *this;
  }
  constexpr Handle operator++(int) {
    Handle h = *this;
    ++index_;
    return h;
  }

  friend constexpr auto operator<=>(Handle, Handle) = default;
  friend constexpr bool operator==(Handle, Handle) = default;

 private:
  uint32_t index_ = 0;
};

// Printed as its index.
template <class Tag>
std::ostream& operator<<(std::ostream& os, Handle<Tag> h) {
  return os << h.index();
}

// The handles [first, last), for range-for loops over a table.
template <class H>
class HandleRange {
 public:
  class iterator {
   public:
    using iterator_category = std::input_iterator_tag;
    using value_type = H;
    using difference_type = std::ptrdiff_t;
    using reference = H;
    using pointer = void;
    constexpr iterator() = default;
    constexpr explicit iterator(H h) : h_(h) {}
    constexpr H operator*() const { return h_; }
    constexpr iterator& operator++() {
      ++h_;
      return *this;
    }
    constexpr iterator operator++(int) { return iterator(h_++); }
    friend constexpr bool operator==(iterator, iterator) = default;

   private:
    H h_;
  };

  constexpr HandleRange(H first, H last) : first_(first), last_(last) {}
  constexpr iterator begin() const { return iterator(first_); }
  constexpr iterator end() const { return iterator(last_); }

 private:
  H first_, last_;
};

// A table indexed by handles of one kind: a std::vector<T> whose operator[] takes an H (and only
// an H), so that a declaration says what indexes the table.
template <class H, class T>
class HandleVector : public std::vector<T> {
  using Base = std::vector<T>;

 public:
  using Base::Base;

  typename Base::reference operator[](H h) { return Base::operator[](h.index()); }
  typename Base::const_reference operator[](H h) const { return Base::operator[](h.index()); }
  typename Base::reference at(H h) { return Base::at(h.index()); }
  typename Base::const_reference at(H h) const { return Base::at(h.index()); }
  // The handles of the entries.
  HandleRange<H> handles() const { return {H(0), H(static_cast<uint32_t>(Base::size()))}; }
};

}  // namespace gmr

template <class Tag>
struct std::hash<gmr::Handle<Tag>> {
  size_t operator()(gmr::Handle<Tag> h) const noexcept { return std::hash<uint32_t>()(h.index()); }
};
