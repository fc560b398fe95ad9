// n-G-maps and n-O-maps as arc-labelled graphs (thesis Def. 32).
//
// Darts are dense uint32_t indices. Links are stored per dimension (structure of arrays):
// link_[i][d] is the target of the i-arc leaving dart d. A free dart is an i-loop (link_[i][d]==d),
// never a null. An n-G-map uses dimensions 0..n, all involutions; an n-O-map uses 1..n, dimension 1
// being a permutation (beta_1, oriented) and 2..n involutions.
//
// The class stores links; it does not enforce the constraints on every write (rules and parsers
// build intermediate states). `check_validity` (validity.hpp) reports every violation, and the
// safe editing operations (sew.hpp) refuse edits that would break validity.
//
// Markers are reusable bitsets (as in CGAL and Jerboa): reserve one, mark darts, unmark them (or
// clear the marker), release it. They live in `mutable` storage so that const traversals can use
// them; a Map is therefore not safe for concurrent traversals.
#pragma once
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string>
#include <type_traits>
#include <vector>

#include "model/core/generated_append.hpp"
#include "model/core/map_spec.hpp"
#include "model/core/orbit_type.hpp"

namespace gmr {

using Dart = uint32_t;
inline constexpr Dart kNoDart = UINT32_MAX;

// A bitset over dart indices; grows with the map.
class Bitset {
 public:
  Bitset() = default;
  // The words go back to the thread's buffer pool (buffer_pool.hpp), as a map's link arrays.
  ~Bitset();
  Bitset(const Bitset&) = default;
  Bitset(Bitset&&) noexcept = default;
  Bitset& operator=(const Bitset&) = default;
  Bitset& operator=(Bitset&&) noexcept = default;

  bool test(Dart d) const { return d < size_ && (words_[d >> 6] >> (d & 63)) & 1u; }
  void set(Dart d) { words_[d >> 6] |= uint64_t(1) << (d & 63); }
  void reset(Dart d) { words_[d >> 6] &= ~(uint64_t(1) << (d & 63)); }
  void resize(size_t n);
  void clear();
  size_t size() const { return size_; }
  size_t bytes() const { return words_.size() * sizeof(uint64_t); }
  size_t count() const;
  // Raw words (bit d of word d/64 is dart d), for hot loops that hoist the indirections.
  uint64_t* data() { return words_.data(); }
  const uint64_t* data() const { return words_.data(); }

 private:
  // Room for `words` words, moved into a pooled or a fresh huge-page array (the old one pooled).
  void grow(size_t words);
  std::vector<uint64_t> words_;
  size_t size_ = 0;
};

// The links of darts being added by Map::add_linked_darts, appended to one link array block by
// block, each written once.
class LinkAppender {
 public:
  // Appends count links: gen(x) for x = 0, 1, ..., count - 1.
  template <class Gen>
  void append(size_t count, Gen&& gen);

 private:
  friend class Map;
  explicit LinkAppender(std::vector<Dart>& links) : links_(links) {}
  std::vector<Dart>& links_;
};

class Map {
 public:
  // An n-G-map (dimensions 0..n) or an n-O-map (dimensions 1..n). n in [0, kMaxDim-1]; for O-maps
  // n >= 1.
  explicit Map(int n, MapKind kind = MapKind::GMap);
  // The link arrays go back to the thread's buffer pool (buffer_pool.hpp) when the map is dropped.
  ~Map();
  Map(const Map&) = default;
  Map(Map&&) noexcept = default;
  Map& operator=(const Map&) = default;
  Map& operator=(Map&&) noexcept = default;

  int dimension() const { return n_; }
  MapKind kind() const { return kind_; }
  MapSpec spec() const { return {n_, kind_}; }
  bool is_omap() const { return kind_ == MapKind::OMap; }
  int lowest_dim() const { return spec().lowest_dim(); }
  bool has_dim(int i) const { return spec().has_dim(i); }
  // Dimensions whose links must be involutions: all for a G-map, 2..n for an O-map.
  bool is_involutive_dim(int i) const { return spec().is_involutive_dim(i); }
  DimMask dims_mask() const;

  // --- darts -------------------------------------------------------------------------------
  // A new dart, free in every dimension (all links are loops). Reuses deleted indices first.
  Dart add_dart();
  // k new consecutive darts at the end of the index range (never reuses deleted ones).
  Dart add_darts(size_t k);
  // k new consecutive darts at the end of the index range, linked as given instead of free: for
  // each dimension i of the map, fill(i, first, out) appends the i-links of darts first..first+k-1
  // in order through `out` (LinkAppender::append). Each link array is written once, with no free
  // state in between; the caller makes the links valid. Throws Error(Usage) if a fill does not
  // append exactly k links; the map is then as before the call (so too if a fill throws).
  template <class Fill>
  Dart add_linked_darts(size_t k, Fill&& fill);
  // Deletes a dart. Darts linked to it become free in that dimension (their link becomes a loop);
  // for beta_1 of an O-map the predecessor's link becomes a loop too.
  void remove_dart(Dart d);
  bool alive(Dart d) const { return d < capacity() && !dead_.test(d); }
  size_t size() const { return capacity() - free_list_.size(); }
  // One past the largest dart index ever used.
  Dart capacity() const { return static_cast<Dart>(capacity_); }
  bool has_holes() const { return !free_list_.empty(); }
  // Room for k darts in every link array (one move of the links when they grow).
  void reserve(size_t k);
  // An empty map given k darts whose links are unspecified (what an earlier use of pooled storage
  // left, buffer_pool.hpp): for a table the caller writes whole through link_data, in any order,
  // before anything reads it. Throws Error(Usage) if the map has darts.
  void resize_for_overwrite(size_t k);

  template <class F>
  void for_each_dart(F&& f) const {
    const Dart cap = capacity();
    if (free_list_.empty()) {
      for (Dart d = 0; d < cap; ++d) f(d);
    } else {
      for (Dart d = 0; d < cap; ++d)
        if (!dead_.test(d)) f(d);
    }
  }
  std::vector<Dart> darts() const;

  // --- links -------------------------------------------------------------------------------
  Dart alpha(int i, Dart d) const { return link_[i][d]; }
  const std::vector<Dart>& links(int i) const { return link_[i]; }
  bool is_free(int i, Dart d) const { return link_[i][d] == d; }
  // i-link a and b in both directions (involutive dimension) — a==b makes a loop. For beta_1 of an
  // O-map: beta_1(a) = b only. No validity check: see sew.hpp for checked edits.
  void link(int i, Dart a, Dart b);
  // Makes d (and its former partner, for involutive dimensions) i-free.
  void unlink(int i, Dart d);
  // Raw one-direction write (for parsers and deliberately broken graphs in tests).
  void set_alpha(int i, Dart d, Dart target) { link_[i][d] = target; }
  // The i-link array itself, for rewrites that write whole blocks of links (no check, no growth).
  Dart* link_data(int i) { return link_[i].data(); }

  // Number of i-links, a loop counting as one link (the papers' convention). For beta_1 of an
  // O-map: number of 1-arcs.
  size_t count_links(int i) const;

  // --- markers -----------------------------------------------------------------------------
  int reserve_marker() const;
  void release_marker(int m) const;  // the marker must be clean (all darts unmarked)
  bool is_marked(Dart d, int m) const { return marks_[m].test(d); }
  void mark(Dart d, int m) const { marks_[m].set(d); }
  void unmark(Dart d, int m) const { marks_[m].reset(d); }
  void clear_marker(int m) const { marks_[m].clear(); }
  // The bitset of a reserved marker (sized to capacity()), for hot loops.
  Bitset& marker_bits(int m) const { return marks_[static_cast<size_t>(m)]; }

  // Bytes held by the map's own arrays (links, dead set, free list, allocated markers).
  size_t memory_bytes() const;

 private:
  // Grows the capacity by k: the limit checked, room for capacity_ + k links (grown_links), the
  // dead set and the markers resized. Returns the first new dart; the link arrays are not written.
  Dart grow_capacity(size_t k);
  // Room for n links in l, moved into a pooled or a fresh huge-page array (the old one pooled).
  static void grown_links(std::vector<Dart>& l, size_t n);
  // Back to capacity `first` (undoes grow_capacity), then throws Error(Usage) naming dimension i.
  [[noreturn]] void refuse_unfilled_links(Dart first, int i);
  void shrink_capacity(Dart first);  // back to capacity `first`, the links past it dropped

  int n_;
  MapKind kind_;
  size_t capacity_ = 0;
  std::vector<std::vector<Dart>> link_;  // link_[i] empty for dimensions the map does not have
  Bitset dead_;
  std::vector<Dart> free_list_;
  mutable std::vector<Bitset> marks_;
  mutable std::vector<bool> marker_used_;
};

// RAII reservation of a marker. The destructor clears the marker (O(capacity/64)) when the user did
// not unmark every dart, then releases it.
class ScopedMarker {
 public:
  explicit ScopedMarker(const Map& g) : g_(g), m_(g.reserve_marker()) {}
  ~ScopedMarker() {
    if (!clean_) g_.clear_marker(m_);
    g_.release_marker(m_);
  }
  ScopedMarker(const ScopedMarker&) = delete;
  ScopedMarker& operator=(const ScopedMarker&) = delete;
  int id() const { return m_; }
  // Promise that every mark was removed by the caller; skips the clearing pass.
  void set_clean() { clean_ = true; }
  bool test(Dart d) const { return g_.is_marked(d, m_); }
  void mark(Dart d) const { g_.mark(d, m_); }
  void unmark(Dart d) const { g_.unmark(d, m_); }

 private:
  const Map& g_;
  int m_;
  bool clean_ = false;
};

template <class Gen>
void LinkAppender::append(size_t count, Gen&& gen) {
  append_generated(links_, count, gen);
}

template <class Fill>
Dart Map::add_linked_darts(size_t k, Fill&& fill) {
  const Dart first = grow_capacity(k);
  for (int i = lowest_dim(); i <= n_; ++i) {
    LinkAppender out(link_[static_cast<size_t>(i)]);
    try {
      fill(i, first, out);
    } catch (...) {
      shrink_capacity(first);
      throw;
    }
    if (link_[static_cast<size_t>(i)].size() != capacity_) refuse_unfilled_links(first, i);
  }
  return first;
}

}  // namespace gmr
