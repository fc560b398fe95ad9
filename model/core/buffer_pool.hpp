// Scratch and large vectors kept by the thread between uses.
//
// A whole-map rewrite writes tables as large as the map (the map's own link arrays and embedding
// slots, orbit indices, classes, memoised values), and fresh memory is paid page by page on first
// touch (a page fault per 4 KiB; several microseconds each on a virtual machine, where this is most
// of a subdivision's time: docs/embeddings.md "Performance"). Applying a scheme again and again
// would pay it at every call. Small maps pay it too: each application's tables, freed to malloc,
// leave the top of the heap free, glibc gives it back to the system (brk, with a TLB flush) and the
// next application faults the same pages in again, which made a subdivision of a 20-face mesh ten
// times slower than its work (docs/embeddings.md "Performance"). So:
//  * take_buffer / give_buffer: a per-thread pool of vectors per element type and per kind of
//    storage (from one page, 4 KiB, of storage; at most 32 per pool, the smallest dropped first);
//    take_buffer(n) returns the smallest pooled vector holding n elements, emptied, or an empty
//    vector when none does or when the smallest is more than twice as large as needed (a small
//    table must not keep a large one);
//  * two kinds of storage, two pools: MapStorage (the default: link arrays, embedding slots and
//    values, bitsets, which live as long as their map) and ScratchTables (the tables of one
//    application: the rewrite's orbit index, the classes and orbit lists of the propagation, the
//    evaluator's memo tables). In one pool the scratch tables of three Loop subdivisions pushed
//    the maps' arrays out and each other (32 entries): about 400 page faults per run in steady
//    state, none with two pools; a single pool of 128 also removed them but made query-replace's
//    sequence (maps only) about 10 % slower warm, cause not established (docs/embeddings.md
//    "Tried and dropped");
//  * Pooled<T, Storage>: a scratch vector taken from a pool (reserve(n) takes one with room for n)
//    and given back to it when destroyed; ScratchTable<T> for the tables of one application.
// Map, Bitset and Embedding give their large arrays back when destroyed and take them when they
// grow, so the storage of a map dropped after one subdivision serves the next (memory is kept by
// the thread until it ends, as a malloc arena keeps its free chunks).
#pragma once
#include <algorithm>
#include <cstddef>
#include <vector>

#include "model/core/huge_pages.hpp"

namespace gmr {

namespace detail {
constexpr size_t kPoolMinBytes = size_t(1) << 12;  // a page
constexpr size_t kPoolMaxBuffers = 32;             // per pool (element type and storage kind)
constexpr size_t kPoolMaxSlack = 2;                // capacity handed out / capacity needed
// Set when the thread's pool is destroyed (a trivially destructible thread_local, readable until
// the thread ends): a map destroyed later (a static one, or a thread_local made before the pool)
// then frees its arrays instead of giving them to a pool that no longer exists.
template <class T, class Storage>
bool& buffer_pool_gone() {
  thread_local bool gone = false;
  return gone;
}
template <class T, class Storage>
struct BufferPool {
  std::vector<std::vector<T>> buffers;
  ~BufferPool() { buffer_pool_gone<T, Storage>() = true; }
};
// The thread's pool, or nullptr once it is destroyed.
template <class T, class Storage>
std::vector<std::vector<T>>* buffer_pool() {
  if (buffer_pool_gone<T, Storage>()) return nullptr;
  thread_local BufferPool<T, Storage> p;
  return &p.buffers;
}
}  // namespace detail

// The kinds of storage, each with its own pools (above).
struct MapStorage;
struct ScratchTables;

// keep_contents: the vector is handed out as it was given back (Pooled::resize_for_overwrite).
template <class T, class Storage = MapStorage>
std::vector<T> take_buffer(size_t min_capacity = 0, bool keep_contents = false) {
  auto* pool = detail::buffer_pool<T, Storage>();
  if (!pool) return {};
  auto& p = *pool;
  size_t best = p.size();
  for (size_t k = 0; k < p.size(); ++k)
    if (p[k].capacity() >= min_capacity &&
        (best == p.size() || p[k].capacity() < p[best].capacity()))
      best = k;
  const size_t needed = std::max(min_capacity, detail::kPoolMinBytes / sizeof(T));
  if (best == p.size() || p[best].capacity() > detail::kPoolMaxSlack * needed) return {};
  std::vector<T> v = std::move(p[best]);
  p.erase(p.begin() + static_cast<std::ptrdiff_t>(best));
  if (!keep_contents) v.clear();
  return v;
}

template <class T, class Storage = MapStorage>
void give_buffer(std::vector<T>&& v) {
  if (v.capacity() * sizeof(T) < detail::kPoolMinBytes) return;
  auto* pool = detail::buffer_pool<T, Storage>();
  if (!pool) return;  // v frees its storage
  auto& p = *pool;
  p.push_back(std::move(v));
  if (p.size() > detail::kPoolMaxBuffers) {
    auto smallest = std::min_element(p.begin(), p.end(), [](const auto& a, const auto& b) {
      return a.capacity() < b.capacity();
    });
    p.erase(smallest);
  }
}

template <class T, class Storage = MapStorage>
class Pooled {
 public:
  Pooled() : v_(take_buffer<T, Storage>()) {}
  ~Pooled() { give_buffer<T, Storage>(std::move(v_)); }
  Pooled(Pooled&& o) noexcept : v_(std::move(o.v_)) {}
  Pooled& operator=(Pooled&& o) noexcept {
    std::swap(v_, o.v_);
    return *this;
  }
  Pooled(const Pooled&) = delete;
  Pooled& operator=(const Pooled&) = delete;

  // Room for n elements: the smallest pooled vector that has it (this one given back), else this
  // one grown in huge pages (huge_pages.hpp). Contents are kept only when no swap happens.
  void reserve(size_t n) { reserve(n, false); }

  // n elements whose values are unspecified (those an earlier use of the storage left): a table
  // the caller writes whole before reading it. A pooled vector that held n elements or more is
  // only cut to n, not filled (a subdivision's tables of every size come back each application).
  void resize_for_overwrite(size_t n) {
    reserve(n, true);
    v_.resize(n);
  }

  std::vector<T>& operator*() { return v_; }
  const std::vector<T>& operator*() const { return v_; }
  std::vector<T>* operator->() { return &v_; }
  const std::vector<T>* operator->() const { return &v_; }

 private:
  void reserve(size_t n, bool keep_contents) {
    if (v_.capacity() >= n) return;
    std::vector<T> other = take_buffer<T, Storage>(n, keep_contents);
    if (other.capacity() >= n) {
      std::swap(v_, other);
      give_buffer<T, Storage>(std::move(other));
      return;
    }
    give_buffer<T, Storage>(std::move(other));
    reserve_in_huge_pages(v_, n);
  }

  std::vector<T> v_;
};

// A table of one application (the ScratchTables pools).
template <class T>
using ScratchTable = Pooled<T, ScratchTables>;

}  // namespace gmr
