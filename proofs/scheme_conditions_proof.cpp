// The scheme conditions of Theorems 4-6 as registered conditions
// (checker/smt/scheme_conditions.hpp), validated through instantiation: every application on every
// G-map of at most `darts` darts (every hook orbit of at most `darts` darts). `scheme-thesis` must
// be sound (Theorems 4-6, the sufficiency direction; Theorem 6 has no other); the two wrong
// variants must be refuted.
#include <gtest/gtest.h>

#include <filesystem>

#include "checker/smt/scheme_conditions.hpp"
#include "model/io/scheme_json.hpp"
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
                                unsigned darts) {
  const SchemeValidationReport r =
      validate_scheme_condition(*find_builtin_scheme_condition(name), family, darts);
  std::printf("%s", to_text(r).c_str());
  return r;
}
}  // namespace

// 16 library schemes and 60 random schemes, G-maps of at most 4 darts.
TEST(Proof, Thm4To6_RegisteredSchemeThesis_Library_Random60_Darts4) {
  const auto family = scheme_family(60);
  const SchemeValidationReport r = validate("scheme-thesis", family, 4);
  EXPECT_TRUE(r.sound()) << to_text(r);
  EXPECT_GT(r.holds, 16u);
}

// The wrong variants are refuted on the same family.
TEST(Proof, Thm4To6_WrongSchemeVariantsRefuted_Library_Random60_Darts4) {
  const auto family = scheme_family(60);
  for (const char* name : {"wrong-scheme-cycle-dropped", "wrong-scheme-dangling-dropped"}) {
    const SchemeValidationReport r = validate(name, family, 4);
    EXPECT_FALSE(r.sound()) << name;
    ASSERT_TRUE(r.smallest_unsound) << name;
    // The counterexample replays (the verifier's replay) and breaks the map or fails the gluing.
    const auto& c = *r.smallest_unsound->result.result->counterexample;
    EXPECT_TRUE(c.gluing_fails || !c.violations.empty()) << name;
  }
}
