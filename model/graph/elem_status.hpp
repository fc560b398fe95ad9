// The status of a node or arc of a rule with respect to its interface L∩R (thesis §2.2 and
// Def. 36 for concrete rules, Def. 46 for rule schemes), and the side of a rule an element lives
// on. Shared by concrete rules (gmr::rewrite), rule schemes (gmr::scheme) and the checker.
#pragma once
#include <cstdint>

namespace gmr::graph {

// Preserved: in L and in R (in L∩R); Deleted: only in L; Added: only in R.
enum class ElemStatus : uint8_t { Preserved, Deleted, Added };

inline const char* to_string(ElemStatus s) {
  switch (s) {
    case ElemStatus::Preserved:
      return "preserved";
    case ElemStatus::Deleted:
      return "deleted";
    case ElemStatus::Added:
      return "added";
  }
  return "?";
}

// The left-hand side L or the right-hand side R of a rule.
enum class Side : uint8_t { L, R };

inline constexpr Side kSides[] = {Side::L, Side::R};

inline const char* to_string(Side s) { return s == Side::L ? "L" : "R"; }
inline Side other(Side s) { return s == Side::L ? Side::R : Side::L; }
// 0 for L, 1 for R: the index of a side in per-side arrays.
inline constexpr unsigned index_of(Side s) { return s == Side::L ? 0 : 1; }

}  // namespace gmr::graph
