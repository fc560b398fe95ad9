// The SMT engine against the enumerator on one rule (checker/smt/rule_verifier.hpp): both give the
// same verdict and applicability, and counterexamples of the same number of darts (both search the
// smallest maps first).
#pragma once
#include <gtest/gtest.h>

#include <string>

#include "checker/smt/rule_verifier.hpp"

namespace gmr::smt {

struct BothVerdicts {
  VerifyResult smt, enumeration;
};

// Both verdicts on r within `bound`, their agreement expected; `where` names r in failures.
inline BothVerdicts verify_both(const Rule& r, unsigned bound, const std::string& where,
                                const EncodingOptions& opt = {}) {
  BothVerdicts v{verify_smt(r, bound, opt), verify_enum(r, bound)};
  EXPECT_EQ(v.smt.preserves, v.enumeration.preserves) << where;
  EXPECT_EQ(v.smt.applicable, v.enumeration.applicable) << where;
  if (!v.smt.preserves && !v.enumeration.preserves) {
    EXPECT_TRUE(v.smt.counterexample && v.enumeration.counterexample) << where;
    if (v.smt.counterexample && v.enumeration.counterexample) {
      EXPECT_EQ(v.smt.counterexample->G.size(), v.enumeration.counterexample->G.size()) << where;
    }
  }
  return v;
}

}  // namespace gmr::smt
