// Validity of an n-G-map / n-O-map (thesis Def. 32) with a report of every violation, each a
// ConstraintViolation located at a dart (constraint_violation.hpp).
//
//  * incidence:   every link targets an existing dart (the stored form always has exactly one
//                 outgoing i-arc per dart; a dangling target breaks I_G(i));
//  * involution:  alpha_i(alpha_i(d)) == d for every involutive dimension (non-orientation O_G(i)
//                 on top of I_G(i)); for beta_1 of an O-map, each dart has exactly one incoming
//                 1-arc (I_G(1), target side);
//  * cycle:       alpha_j(alpha_i(alpha_j(alpha_i(d)))) == d for i+2 <= j (C_G(i,j)); for O-maps
//                 over (1..n)_{+2} only (Def. 32, not the combinatorial Def. 1).
#pragma once
#include <vector>

#include "model/core/constraint_violation.hpp"
#include "model/core/map.hpp"

namespace gmr {

struct ValidityReport {
  std::vector<ConstraintViolation> violations;
  size_t truncated = 0;  // violations not stored (beyond the limit)
  bool ok() const { return violations.empty() && truncated == 0; }
  size_t total() const { return violations.size() + truncated; }
};

// Reports every violation (at most `limit` stored; the rest are counted in `truncated`).
ValidityReport check_validity(const Map& g, size_t limit = 1000);
bool is_valid(const Map& g);

}  // namespace gmr
