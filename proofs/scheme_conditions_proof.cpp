// The scheme conditions of Theorems 4-6 as registered conditions
// (checker/smt/scheme_conditions.hpp), validated through instantiation: every application on every
// G-map of at most `darts` darts (every hook orbit of at most `darts` darts). `scheme-thesis` must
// be sound (Theorems 4-6, the sufficiency direction; Theorem 6 has no other); the two wrong
// variants must be refuted.
#include <gtest/gtest.h>

#include <filesystem>

#include "checker/smt/scheme_conditions.hpp"
#include "checker/smt/validation_format.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "model/testing/random_schemes.hpp"
#include "model/testing/source_tree.hpp"

using namespace gmr;
using namespace gmr::smt;

namespace {
// The library operations and the random schemes of seeds 0..seeds-1
// (model/testing/random_schemes.hpp).
std::vector<RuleScheme> scheme_family(uint64_t seeds) {
  std::vector<RuleScheme> out;
  for (const auto& e :
       std::filesystem::directory_iterator(gmr::testing::source_path("tools/data/rules")))
    if (e.path().extension() == ".json") out.push_back(io::read_scheme_file(e.path()));
  for (uint64_t seed = 0; seed < seeds; ++seed) {
    gmr::testing::Rng rng(seed);
    out.push_back(gmr::testing::random_scheme(rng));
  }
  return out;
}
SchemeValidationReport validate(const std::string& name, const std::vector<RuleScheme>& family,
                                const SchemeFamilyVerdicts& verdicts) {
  const std::vector<bool> holds =
      evaluate_scheme_condition(*find_builtin_scheme_condition(name), family);
  const SchemeValidationReport r = classify_scheme_condition(name, holds, family, verdicts);
  std::printf("%s", to_text(r).c_str());
  return r;
}
}  // namespace

// 16 library schemes and 60 random schemes, G-maps of at most 4 darts: every scheme verified once,
// then each condition classified against those verdicts. `scheme-thesis` is sound; the wrong
// variants are refuted.
TEST(Proof, Thm4To6_RegisteredSchemeConditions_Library_Random60_Darts4) {
  const auto family = scheme_family(60);
  const SchemeFamilyVerdicts verdicts = verify_scheme_family(family, 4);
  const SchemeValidationReport thesis = validate("scheme-thesis", family, verdicts);
  EXPECT_TRUE(thesis.sound()) << to_text(thesis);
  EXPECT_GT(thesis.holds, 16u);
  for (const char* name : {"wrong-scheme-cycle-dropped", "wrong-scheme-dangling-dropped"}) {
    const SchemeValidationReport r = validate(name, family, verdicts);
    EXPECT_FALSE(r.sound()) << name;
    ASSERT_TRUE(r.smallest_unsound) << name;
    // The counterexample replays (the verifier's replay) and breaks the map or fails the gluing.
    const auto& c = *r.smallest_unsound->result.result->counterexample;
    EXPECT_TRUE(c.gluing_fails || !c.violations.empty()) << name;
  }
}
