// The status of a node or arc of a rule with respect to its interface L∩R (thesis §2.2 and
// Def. 36 for concrete rules, Def. 46 for rule schemes), and the side of a rule an element lives on.
// Shared by concrete rules (gmr::rewrite), rule schemes (gmr::scheme) and the checker.
#pragma once
#include <cstdint>

namespace gmr::graph {

// Preserved: in L and in R (in L∩R); Deleted: only in L; Added: only in R.
enum class ElemStatus : uint8_t { Preserved, Deleted, Added };

inline const char* to_string(ElemStatus s) {
  switch (s) {
    case ElemStatus::Preserved: return "preserved";
    case ElemStatus::Deleted: return "deleted";
    case ElemStatus::Added: return "added";
  }
  return "?";
}

// The left-hand side L or the right-hand side R of a rule.
enum class Side : uint8_t { L, R };

inline const char* to_string(Side s) { return s == Side::L ? "L" : "R"; }
inline Side other(Side s) { return s == Side::L ? Side::R : Side::L; }
inline Side side_of(bool right) { return right ? Side::R : Side::L; }
inline bool is_right(Side s) { return s == Side::R; }

}  // namespace gmr::graph
