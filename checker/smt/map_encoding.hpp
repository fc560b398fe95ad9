// G-maps and O-maps of at most k darts as Z3 formulas (thesis Defs. 31-32; docs/verify.md).
//
// Darts are the numerals 0..k-1 of a dart sort (mathematical integers, or bit-vectors of
// ceil(log2(k+extra)) bits: the encoding choice measured in docs/verify.md). The map has `size`
// darts, 1 <= size <= k, and its darts are the numerals below `size` (symmetry breaking: every map
// of at most k darts is isomorphic to one whose darts are 0..size-1). Each label i of the model is
// an uninterpreted function alpha_i on the dart sort, constrained on the active darts only:
//   range        0 <= alpha_i(d) < size;
//   I(i)         alpha_i a permutation: for an involutive label alpha_i(alpha_i(d)) = d, for the
//                oriented label 1 of an O-map an inverse function beta_1^-1 with both compositions
//                the identity (so every dart has exactly one outgoing and one incoming i-arc);
//   O(i)         alpha_i an involution (involutive labels: 0..n for a G-map, 2..n for an O-map);
//   C(i,j)       alpha_j(alpha_i(alpha_j(alpha_i(d)))) = d for the model's cycle pairs.
// Loops are fixed points (a free dart is an i-loop).
#pragma once
#include <z3++.h>

#include <string>
#include <vector>

#include "model/core/map_spec.hpp"

namespace gmr::smt {

enum class DartSort { Int, BitVec };
const char* to_string(DartSort s);

class MapEncoding {
 public:
  // `capacity` darts of G (the bound k); `extra` further numerals reserved for the nodes a
  // derivation adds (so the bit-vector width covers them). `prefix` names the map's symbols, so
  // that several maps can live in one context (the instances of symbolic_validation.hpp).
  MapEncoding(z3::context& ctx, MapSpec spec, unsigned capacity, unsigned extra = 0,
              DartSort sort = DartSort::Int, const std::string& prefix = "");

  z3::context& ctx() const { return ctx_; }
  const MapSpec& spec() const { return spec_; }
  unsigned capacity() const { return capacity_; }
  DartSort dart_sort() const { return sort_kind_; }
  z3::sort sort() const { return sort_; }

  // The numeral of dart (or node) index v.
  z3::expr dart(unsigned v) const;
  // a < b and a <= b on the dart sort (unsigned for bit-vectors).
  z3::expr lt(const z3::expr& a, const z3::expr& b) const;
  // The number of darts of the map (a dart-sort constant).
  const z3::expr& size() const { return size_; }
  // Dart v exists in the map: v < size.
  z3::expr active(unsigned v) const { return lt(dart(v), size_); }
  // A dart term denotes an existing dart: 0 <= t < size.
  z3::expr active_term(const z3::expr& t) const;
  // alpha_i (beta_i for an O-map) applied to a dart term.
  z3::expr alpha(int i, const z3::expr& d) const;
  // The inverse of alpha_i: alpha_i itself for an involutive label, beta_1^-1 for an O-map.
  z3::expr alpha_inverse(int i, const z3::expr& d) const;

  // The constraints of the model (Def. 32) on darts 0..capacity-1 and 1 <= size <= capacity.
  z3::expr_vector constraints() const;

 private:
  z3::context& ctx_;
  MapSpec spec_;
  unsigned capacity_;
  DartSort sort_kind_;
  z3::sort sort_;
  z3::expr size_;
  std::vector<z3::func_decl> alpha_;    // indexed by label
  std::vector<z3::func_decl> inverse_;  // only used for non-involutive labels
};

}  // namespace gmr::smt
