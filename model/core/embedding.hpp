// Embeddings (thesis Ch. 5, Def. 5x; Jerboa): a named attribute attached to an orbit type, with one
// value per orbit. Storage: each dart holds the index of its orbit's value slot (kNoValue when
// unset), as Jerboa's per-dart reference `d.pi`.
// Consistency (every dart of an <o>-orbit holds the same value; every dart holds one) is checked by
// `check`, which reports each offending orbit.
#pragma once
#include <algorithm>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "model/core/buffer_pool.hpp"
#include "model/core/error.hpp"
#include "model/core/generated_append.hpp"
#include "model/core/huge_pages.hpp"
#include "model/core/map.hpp"
#include "model/core/orbit.hpp"

namespace gmr {

struct EmbeddingIssue {
  Dart dart;            // a dart of the offending orbit
  std::string problem;  // "no value", "2 different values in the orbit"
};

template <class T>
class Embedding {
 public:
  static constexpr uint32_t kNoValue = UINT32_MAX;

  Embedding(std::string name, OrbitType orbit_type)
      : name_(std::move(name)), orbit_(std::move(orbit_type)) {}
  // The slot table and the values go back to the thread's buffer pool (buffer_pool.hpp).
  ~Embedding() {
    give_buffer(std::move(slot_));
    give_buffer(std::move(values_));
  }
  Embedding(const Embedding&) = default;
  Embedding(Embedding&&) noexcept = default;
  Embedding& operator=(const Embedding&) = default;
  Embedding& operator=(Embedding&&) noexcept = default;

  const std::string& name() const { return name_; }
  const OrbitType& orbit_type() const { return orbit_; }

  // Gives value v to the whole <o>-orbit of d.
  void set(const Map& g, Dart d, T v) {
    grow(g);
    const auto slot = static_cast<uint32_t>(values_.size());
    values_.push_back(std::move(v));
    for (Dart e : orbit(g, orbit_, d)) slot_[e] = slot;
  }
  // Raw per-dart write (parsers; deliberately inconsistent data in tests).
  void set_dart(const Map& g, Dart d, T v) {
    grow(g);
    slot_[d] = static_cast<uint32_t>(values_.size());
    values_.push_back(std::move(v));
  }
  bool has(Dart d) const { return d < slot_.size() && slot_[d] != kNoValue; }

  // Slot-level access, for the propagation of values after a rewrite (thesis §5.3, Jerboa's
  // per-dart reference): a new value slot, the slot of a dart, and the assignment of a slot.
  uint32_t add_value(T v) {
    values_.push_back(std::move(v));
    return static_cast<uint32_t>(values_.size() - 1);
  }
  // add_value of each of vs, in order (their slots follow the last one's).
  void append_values(std::span<const T> vs) {
    reserve_values(values_.size() + vs.size());
    values_.insert(values_.end(), vs.begin(), vs.end());
  }
  void reserve_values(size_t n) {
    if (values_.capacity() < n) regrow(values_, std::max(n, 2 * values_.capacity()));
  }
  // Values appended by fill(values), which is given the value array itself and only pushes onto its
  // end (no buffer of its own copied in). A reader holding values() keeps a valid span only while
  // the array stays within the capacity it had (reserve_values first).
  template <class Fill>
  void append_values_by(Fill&& fill) {
    fill(values_);
  }
  // The values from slot n on dropped (appended for a rewrite that did not happen).
  void truncate_values(size_t n) {
    if (n < values_.size())
      values_.erase(values_.begin() + static_cast<std::ptrdiff_t>(n), values_.end());
  }
  uint32_t slot(Dart d) const { return d < slot_.size() ? slot_[d] : kNoValue; }
  // The slot table (slot(d) for d below its size) and the values, for readers that hold them
  // while neither changes.
  std::span<const uint32_t> slots() const { return slot_; }
  std::span<const T> values() const { return values_; }
  void set_slot(const Map& g, Dart d, uint32_t s) {
    grow(g);
    slot_[d] = s;
  }
  // Sizes the slot table to g's capacity (new darts without value), for set_slot_unchecked.
  void fit(const Map& g) { grow(g); }
  // The slots of the next n darts (from slots().size() on): gen(x) for x = 0..n-1, each written
  // once (generated_append.hpp; fit would first write kNoValue).
  template <class Gen>
  void append_slots(size_t n, const Gen& gen) {
    reserve_slots(slot_.size() + n);
    append_generated(slot_, n, gen);
  }
  // The same with gen(x) = offset + classes[x]: the classes copied, then offset added to each (two
  // passes the compiler vectorises, where a generator is one call per slot).
  void append_slots_offset(const uint32_t* classes, size_t n, uint32_t offset) {
    reserve_slots(slot_.size() + n);
    const size_t first = slot_.size();
    slot_.insert(slot_.end(), classes, classes + n);
    uint32_t* const s = slot_.data() + first;
    for (size_t x = 0; x < n; ++x) s[x] += offset;
  }
  // Room for n slots (appends up to n copy no slot); geometric, as the appends grow it.
  void reserve_slots(size_t n) {
    if (slot_.capacity() < n) regrow(slot_, std::max(n, 2 * slot_.capacity()));
  }
  // set_slot without sizing: d must be below the size reached by an earlier set_slot/set.
  void set_slot_unchecked(Dart d, uint32_t s) { slot_[d] = s; }
  const T& value(uint32_t s) const { return values_[s]; }
  size_t num_values() const { return values_.size(); }
  const T& get(Dart d) const {
    if (!has(d))
      throw Error(ErrorCode::Range, "embedding '" + name_ + "' has no value",
                  "dart " + std::to_string(d));
    return values_[slot_[d]];
  }

  // Every orbit whose darts do not all hold one value (values compared with ==).
  std::vector<EmbeddingIssue> check(const Map& g) const {
    require_orbit_type(g, orbit_);
    std::vector<EmbeddingIssue> issues;
    for (Dart rep : orbit_representatives(g, orbit_)) {
      const auto darts = orbit(g, orbit_, rep);
      if (!has(rep)) {
        issues.push_back({rep, "no value on this " + orbit_.str() + "-orbit"});
        continue;
      }
      for (Dart e : darts) {
        if (!has(e)) {
          issues.push_back({e, "dart has no value while its " + orbit_.str() + "-orbit has one"});
          break;
        }
        if (!(values_[slot_[e]] == values_[slot_[rep]])) {
          issues.push_back({e, "two different values in one " + orbit_.str() + "-orbit (darts " +
                                   std::to_string(rep) + " and " + std::to_string(e) + ")"});
          break;
        }
      }
    }
    return issues;
  }

 private:
  void grow(const Map& g) {
    if (slot_.size() >= g.capacity()) return;
    if (slot_.capacity() < g.capacity())
      regrow(slot_, std::max<size_t>(g.capacity(), 2 * slot_.size()));
    slot_.resize(g.capacity(), kNoValue);
  }
  // v with room for n elements: a pooled or fresh (huge-page) array, the old one pooled.
  template <class V>
  static void regrow(V& v, size_t n) {
    V grown = take_buffer<typename V::value_type>(n);
    reserve_in_huge_pages(grown, n);
    grown.assign(v.begin(), v.end());
    give_buffer(std::move(v));
    v = std::move(grown);
  }
  std::string name_;
  OrbitType orbit_;
  std::vector<uint32_t> slot_;
  std::vector<T> values_;
};

}  // namespace gmr
