// Larger bound of the rule-scheme proof through instantiation (label slow; proofs/README.md).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "checker/scheme_checker.hpp"
#include "checker/smt/scheme_verifier.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "model/testing/source_tree.hpp"

using namespace gmr;
using namespace gmr::smt;

// The library operations (tools/data/rules): no application on a G-map of at most 7 darts (every
// hook orbit of at most 7 darts) breaks it.
TEST(ProofSlow, Thm4To6_LibrarySchemes_Darts7) {
  size_t n = 0;
  for (const auto& e :
       std::filesystem::directory_iterator(gmr::testing::source_path("tools/data/rules"))) {
    if (e.path().extension() != ".json") continue;
    const RuleScheme s = io::read_scheme_file(e.path());
    ASSERT_TRUE(checker::check_scheme(s).ok()) << s.name;
    const SchemeVerifyResult v = verify_scheme(s, 7, Engine::Smt);
    std::printf("  %-28s %zu hook orbits, %zu applicable, %.2fs\n", s.name.c_str(), v.orbits,
                v.applicable, v.seconds);
    EXPECT_TRUE(v.preserves) << s.name;
    ++n;
  }
  EXPECT_EQ(n, 16u);  // every file of the library
}
