// Large arrays in transparent huge pages.
//
// The first write to a fresh 4 KiB page costs a page fault; on a virtual machine that is several
// microseconds, and a map growing by millions of darts takes tens of thousands of them (the
// profile of the subdivision benchmark, docs/embeddings.md "Performance"). Where the system's
// policy is `madvise` (the usual default), an anonymous range advised with MADV_HUGEPAGE is faulted
// in 2 MiB pages instead: 512 times fewer faults. Only the 2 MiB-aligned part of a range of at
// least 4 MiB is advised; elsewhere (other systems, smaller ranges) this does nothing. The advice
// is a hint: contents and semantics are unchanged.
#pragma once
#include <algorithm>
#include <cstddef>
#include <iterator>

namespace gmr {

void advise_huge_pages(const void* data, size_t bytes);

// v.reserve(n), the new storage advised (for a vector about to grow into it) before v's elements
// are moved into it: v.reserve would write them first, faulting their pages in 4 KiB.
template <class V>
void reserve_in_huge_pages(V& v, size_t n) {
  if (v.capacity() >= n) return;
  V grown;
  grown.reserve(n);
  advise_huge_pages(grown.data(), grown.capacity() * sizeof(typename V::value_type));
  grown.insert(grown.end(), std::make_move_iterator(v.begin()), std::make_move_iterator(v.end()));
  v.swap(grown);
}

// Room for n elements in v: when it grows, at least twice the room it had, advised (an array that
// grows with its map).
template <class V>
void grow_in_huge_pages(V& v, size_t n) {
  if (v.capacity() < n) reserve_in_huge_pages(v, std::max(n, 2 * v.capacity()));
}

// v grown to n elements, the new ones set to `value` (grow_in_huge_pages: a per-dart table).
template <class V>
void resize_in_huge_pages(V& v, size_t n, const typename V::value_type& value) {
  if (v.size() >= n) return;
  grow_in_huge_pages(v, n);
  v.resize(n, value);
}

}  // namespace gmr
