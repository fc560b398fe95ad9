// Orbit types in the papers' notation: <0,1,2>, <_,1,2>, <>.
// A plain orbit type is a set of dimensions (thesis Def. 56). A node label of a rule scheme is a
// positional relabeling of the hook's orbit type (thesis Def. 86), where `_` deletes the links of
// that position; OrbitType stores both, with kHole for `_`.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace gmr {

using DimMask = uint32_t;  // bit i set <=> dimension i belongs to the orbit type
inline constexpr int kMaxDim = 31;

class OrbitType {
 public:
  static constexpr int kHole = -1;  // `_`

  OrbitType() = default;
  explicit OrbitType(std::vector<int> dims) : dims_(std::move(dims)) {}
  OrbitType(std::initializer_list<int> dims) : dims_(dims) {}

  // Parses "<0,_,2>" (spaces allowed). Throws Error(Parse) naming the offending character.
  static OrbitType parse(std::string_view text);
  // All dimensions 0..n except `except` (the i-cell orbit type of an n-G-map).
  static OrbitType cell(int n, int i);
  // <lo..hi>
  static OrbitType range(int lo, int hi);

  const std::vector<int>& dims() const { return dims_; }
  size_t size() const { return dims_.size(); }
  int operator[](size_t p) const { return dims_[p]; }
  bool has_hole() const;
  // Set of dimensions (holes skipped).
  DimMask mask() const;
  bool contains(int dim) const;
  std::string str() const;  // "<0,_,2>"

  friend bool operator==(const OrbitType&, const OrbitType&) = default;

 private:
  std::vector<int> dims_;
};

}  // namespace gmr
