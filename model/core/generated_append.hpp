// Appending generated elements to a vector, each written once into its final place: gen(x) for
// x = 0..n-1 is constructed at the end (vector::insert from a forward range), with no
// value-initialised state first (as resize would write) and no per-element size update (as
// push_back does). Growth is vector::insert's (geometric), so the appended elements may be computed
// from the vector's own elements only through copies taken before the call.
#pragma once
#include <cstddef>
#include <iterator>
#include <type_traits>
#include <vector>

namespace gmr {

namespace detail {
// gen(x) for x = first, first + 1, ...: a forward iterator, so that vector::insert writes each
// element once into its final place.
template <class T, class Gen>
class GeneratedIterator {
 public:
  using iterator_category = std::forward_iterator_tag;
  using value_type = T;
  using difference_type = std::ptrdiff_t;
  using pointer = const T*;
  using reference = T;
  GeneratedIterator() = default;
  GeneratedIterator(const Gen* gen, size_t x) : gen_(gen), x_(x) {}
  T operator*() const { return (*gen_)(x_); }
  GeneratedIterator& operator++() {
    ++x_;
    return *this;
  }
  GeneratedIterator operator++(int) {
    GeneratedIterator old = *this;
    ++x_;
    return old;
  }
  bool operator==(const GeneratedIterator& o) const { return x_ == o.x_; }

 private:
  const Gen* gen_ = nullptr;
  size_t x_ = 0;
};
}  // namespace detail

template <class T, class Gen>
void append_generated(std::vector<T>& v, size_t n, const Gen& gen) {
  using It = detail::GeneratedIterator<T, Gen>;
  v.insert(v.end(), It(&gen, 0), It(&gen, n));
}

}  // namespace gmr
