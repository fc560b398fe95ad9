#include "model/core/map.hpp"

#include <algorithm>
#include <bit>
#include <ranges>

#include "model/core/buffer_pool.hpp"
#include "model/core/error.hpp"
#include "model/core/huge_pages.hpp"

namespace gmr {

const char* to_string(MapKind kind) { return kind == MapKind::GMap ? "gmap" : "omap"; }

Bitset::~Bitset() { give_buffer(std::move(words_)); }

void Bitset::resize(size_t n) {
  const size_t words = (n + 63) / 64;
  if (words > words_.capacity()) grow(std::max(words, 2 * words_.size()));
  words_.resize(words, 0);
  if (n < size_ && n % 64 != 0)
    words_.back() &= (uint64_t(1) << (n % 64)) - 1;  // bits past n read 0 when regrown
  size_ = n;
}

void Bitset::grow(size_t words) {
  std::vector<uint64_t> grown = take_buffer<uint64_t>(words);
  reserve_in_huge_pages(grown, words);
  grown.assign(words_.begin(), words_.end());
  give_buffer(std::move(words_));
  words_ = std::move(grown);
}

void Bitset::clear() { std::fill(words_.begin(), words_.end(), 0); }

size_t Bitset::count() const {
  size_t c = 0;
  for (uint64_t w : words_) c += static_cast<size_t>(std::popcount(w));
  return c;
}

Map::Map(int n, MapKind kind) : n_(n), kind_(kind) {
  if (n < 0 || n >= kMaxDim)
    throw Error(ErrorCode::Range,
                "dimension " + std::to_string(n) + " outside 0.." + std::to_string(kMaxDim - 1));
  if (kind == MapKind::OMap && n < 1)
    throw Error(ErrorCode::Range, "an n-O-map needs n >= 1 (dimensions 1..n)");
  link_.resize(static_cast<size_t>(n) + 1);
}

Map::~Map() {
  for (auto& l : link_) give_buffer(std::move(l));
}

DimMask Map::dims_mask() const {
  DimMask m = 0;
  for (int i = lowest_dim(); i <= n_; ++i) m |= DimMask(1) << i;
  return m;
}

void Map::reserve(size_t k) {
  for (int i = lowest_dim(); i <= n_; ++i) grown_links(link_[i], k);
}

void Map::grown_links(std::vector<Dart>& l, size_t n) {
  if (l.capacity() >= n) return;
  // Into a pooled or a fresh (huge-page) array, the old one pooled.
  std::vector<Dart> grown = take_buffer<Dart>(n);
  reserve_in_huge_pages(grown, n);
  grown.assign(l.begin(), l.end());
  give_buffer(std::move(l));
  l = std::move(grown);
}

void Map::resize_for_overwrite(size_t k) {
  if (capacity_ != 0)
    throw Error(ErrorCode::Usage, "resize_for_overwrite of a map that has darts",
                "capacity " + std::to_string(capacity_));
  if (k >= kNoDart)
    throw Error(ErrorCode::Range, "too many darts (limit " + std::to_string(kNoDart - 1) + ")");
  for (int i = lowest_dim(); i <= n_; ++i) {
    auto& l = link_[i];
    if (l.capacity() < k) {
      // A pooled array is taken as it was given back: cut to k, not filled, when it held k links.
      give_buffer(std::move(l));
      l = take_buffer<Dart>(k, /*keep_contents=*/true);
      reserve_in_huge_pages(l, k);
    }
    l.resize(k);
  }
  capacity_ = k;
  dead_.resize(capacity_);
  for (auto& m : marks_) m.resize(capacity_);
}

Dart Map::grow_capacity(size_t k) {
  if (capacity_ + k >= kNoDart)
    throw Error(ErrorCode::Range, "too many darts (limit " + std::to_string(kNoDart - 1) + ")");
  const Dart first = capacity();
  capacity_ += k;
  for (int i = lowest_dim(); i <= n_; ++i) {
    auto& l = link_[i];
    if (l.capacity() < capacity_) grown_links(l, std::max(capacity_, 2 * l.size()));
  }
  dead_.resize(capacity_);
  for (auto& m : marks_) m.resize(capacity_);
  return first;
}

void Map::shrink_capacity(Dart first) {
  capacity_ = first;
  for (int i = lowest_dim(); i <= n_; ++i)
    if (link_[i].size() > capacity_) link_[i].resize(capacity_);
  dead_.resize(capacity_);
  for (auto& m : marks_) m.resize(capacity_);
}

void Map::refuse_unfilled_links(Dart first, int i) {
  const size_t given = link_[i].size() - std::min<size_t>(link_[i].size(), first),
               wanted = capacity_ - first;
  shrink_capacity(first);
  throw Error(ErrorCode::Usage,
              "adding " + std::to_string(wanted) + " linked darts, " + std::to_string(given) + " " +
                  std::to_string(i) + "-links were given",
              "dart " + std::to_string(first));
}

Dart Map::add_darts(size_t k) {
  // New darts are free (a loop at every dimension): written once, without a zero fill first.
  return add_linked_darts(k, [k](int, Dart first, LinkAppender& out) {
    out.append(k, [first](size_t x) { return first + static_cast<Dart>(x); });
  });
}

Dart Map::add_dart() {
  if (!free_list_.empty()) {
    const Dart d = free_list_.back();
    free_list_.pop_back();
    dead_.reset(d);
    for (int i = lowest_dim(); i <= n_; ++i) link_[i][d] = d;
    return d;
  }
  return add_darts(1);
}

void Map::remove_dart(Dart d) {
  if (!alive(d))
    throw Error(ErrorCode::Range, "remove of a dart that does not exist",
                "dart " + std::to_string(d));
  for (int i = lowest_dim(); i <= n_; ++i) {
    auto& l = link_[i];
    const Dart e = l[d];
    if (is_involutive_dim(i)) {
      if (e != d && e < capacity_ && l[e] == d) l[e] = e;
    } else {
      // beta_1: find the predecessor through the cycle starting at d (O(face size)).
      Dart p = d;
      size_t guard = 0;
      while (l[p] != d && guard++ < capacity_) {
        p = l[p];
        if (p >= capacity_) break;
      }
      if (p < capacity_ && p != d && l[p] == d) l[p] = p;
    }
    l[d] = d;
  }
  dead_.set(d);
  for (auto& m : marks_) m.reset(d);
  free_list_.push_back(d);
}

std::vector<Dart> Map::darts() const {
  std::vector<Dart> out;
  out.reserve(size());
  for_each_dart([&](Dart d) { out.push_back(d); });
  return out;
}

void Map::link(int i, Dart a, Dart b) {
  link_[i][a] = b;
  if (is_involutive_dim(i)) link_[i][b] = a;
}

void Map::unlink(int i, Dart d) {
  const Dart e = link_[i][d];
  link_[i][d] = d;
  if (is_involutive_dim(i) && e != d && link_[i][e] == d) link_[i][e] = e;
}

size_t Map::count_links(int i) const {
  size_t loops = 0, arcs = 0;
  const auto& l = link_[i];
  for_each_dart([&](Dart d) {
    if (l[d] == d)
      ++loops;
    else
      ++arcs;
  });
  return is_involutive_dim(i) ? loops + arcs / 2 : loops + arcs;
}

int Map::reserve_marker() const {
  for (size_t m = 0; m < marker_used_.size(); ++m) {
    if (!marker_used_[m]) {
      marker_used_[m] = true;
      marks_[m].resize(capacity_);
      return static_cast<int>(m);
    }
  }
  marks_.emplace_back();
  marks_.back().resize(capacity_);
  marker_used_.push_back(true);
  return static_cast<int>(marks_.size() - 1);
}

void Map::release_marker(int m) const { marker_used_[static_cast<size_t>(m)] = false; }

size_t Map::memory_bytes() const {
  size_t b = sizeof(*this) + dead_.bytes() + free_list_.capacity() * sizeof(Dart);
  for (const auto& l : link_) b += l.capacity() * sizeof(Dart);
  for (const auto& m : marks_) b += m.bytes();
  return b;
}

}  // namespace gmr
