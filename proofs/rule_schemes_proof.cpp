// Bounded proofs of the rule-scheme theorems through instantiation (Theorems 4-6, thesis Ch. 4):
// a scheme accepted by the scheme checker (I_S, O_S, C_S) preserves G-maps, checked on every
// G-map of at most `darts` darts and every hook orbit of at most `darts` darts
// (checker/smt/scheme_verifier.hpp). This is the sufficiency direction of Theorems 4-6 (Theorem 6
// has no other); the necessity of Theorems 4-5 quantifies over pattern graphs that need not be
// orbits of small maps and is not covered (proofs/README.md).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "checker/scheme_checker.hpp"
#include "checker/smt/scheme_verifier.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "model/testing/random_schemes.hpp"
#include "model/testing/source_tree.hpp"

using namespace gmr;
using namespace gmr::smt;

namespace {
std::filesystem::path root() { return gmr::testing::source_path("."); }
}  // namespace

// The library operations (tools/data/rules), all accepted: no application on a G-map of at most
// 5 darts breaks it.
TEST(Proof, Thm4To6_LibrarySchemes_Darts5) {
  size_t n = 0;
  for (const auto& e : std::filesystem::directory_iterator(root() / "tools/data/rules")) {
    if (e.path().extension() != ".json") continue;
    const RuleScheme s = io::read_scheme_file(e.path());
    ASSERT_TRUE(checker::check_scheme(s).ok()) << s.name;
    const SchemeVerifyResult v = verify_scheme(s, 5, Engine::Smt);
    std::printf("  %-28s %zu hook orbits, %zu applicable, %.2fs\n", s.name.c_str(), v.orbits,
                v.applicable, v.seconds);
    EXPECT_TRUE(v.preserves) << s.name;
    ++n;
  }
  EXPECT_EQ(n, 16u);  // every file of the library
}

// Random schemes of 2-G-maps (model/testing/random_schemes.hpp, seeds 0..199): every accepted one
// preserves G-maps of at most 4 darts; the rejected ones are counted (rejection is not refuted:
// Theorem 6 is sufficient only).
TEST(Proof, Thm4To6_RandomSchemes_Seeds200_Darts4) {
  size_t accepted = 0, rejected = 0, broken_rejected = 0;
  for (uint64_t seed = 0; seed < 200; ++seed) {
    gmr::testing::Rng rng(seed);
    const RuleScheme s = gmr::testing::random_scheme(rng);
    const bool ok = checker::check_scheme(s).ok();
    const SchemeVerifyResult v = verify_scheme(s, 4, Engine::Smt);
    if (ok) {
      ++accepted;
      EXPECT_TRUE(v.preserves) << "seed " << seed << ": accepted scheme " << s.name
                               << " breaks a map";
    } else {
      ++rejected;
      broken_rejected += !v.preserves;
    }
  }
  std::printf("accepted %zu, rejected %zu (of which %zu break a map of at most 4 darts)\n",
              accepted, rejected, broken_rejected);
  EXPECT_GT(accepted, 0u);
}
