// The SMT engine against the enumerator on small hand-written rules (checker/tests/data).
#include "checker/smt/rule_verifier.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "checker/smt/tests/both_engines.hpp"
#include "model/rule_io/rule_json.hpp"
#include "model/testing/rule_family.hpp"
#include "model/testing/source_tree.hpp"

using namespace gmr;
using namespace gmr::smt;

namespace {
std::filesystem::path fixtures() { return gmr::testing::source_path("checker/tests/data"); }
}  // namespace

TEST(RuleVerifier, FixturesSmtAgreesWithEnumerator) {
  size_t n = 0;
  for (const auto& e : std::filesystem::directory_iterator(fixtures())) {
    if (e.path().extension() != ".json") continue;
    const Rule r = io::read_rule_file(e.path());
    const unsigned bound = r.dimension() <= 1 ? 6 : 4;
    const auto [s, m] = verify_both(r, bound, e.path().string());
    std::printf("%-40s smt %s%s %.3fs  enum %s%s %.3fs\n", e.path().stem().c_str(),
                s.preserves ? "ok" : "BREAKS", s.applicable ? "" : " (vacuous)", s.seconds,
                m.preserves ? "ok" : "BREAKS", m.applicable ? "" : " (vacuous)", m.seconds);
    ++n;
  }
  EXPECT_GT(n, 10u);
}

namespace {
// Every rule of the family: the two engines agree (both_engines.hpp).
// Every `stride`-th rule of the family (the whole family takes about a minute per case).
void compare_family(int n, MapKind kind, int max_nodes, const std::vector<int>& labels,
                    unsigned bound, size_t stride, const EncodingOptions& opt = {}) {
  size_t rules = 0, breaks = 0, vacuous = 0, seen = 0;
  gmr::testing::for_each_small_rule(n, kind, max_nodes, labels, [&](const Rule& r) {
    if (seen++ % stride) return true;
    ++rules;
    const VerifyResult m = verify_both(r, bound, io::rule_to_json(r).dump(), opt).enumeration;
    breaks += !m.preserves;
    vacuous += !m.applicable;
    return !::testing::Test::HasFailure();
  });
  std::printf("%zu rules: %zu break the model, %zu never apply within %u darts\n", rules, breaks,
              vacuous, bound);
  EXPECT_GT(breaks, 0u);
  EXPECT_LT(breaks + vacuous, rules);
}
}  // namespace

TEST(RuleVerifier, Family1GMaps2Nodes) { compare_family(1, MapKind::GMap, 2, {0, 1}, 4, 7); }
TEST(RuleVerifier, Family2GMaps2NodesCyclePair) {
  compare_family(2, MapKind::GMap, 2, {0, 2}, 4, 7);
}
TEST(RuleVerifier, Family2OMaps2Nodes) { compare_family(2, MapKind::OMap, 2, {1, 2}, 4, 7); }
TEST(RuleVerifier, FamilyIntFreeMatchFreshSolversGlobal) {
  compare_family(1, MapKind::GMap, 2, {0, 1}, 4, 11,
                 {DartSort::Int, false, false, Semantics::Preservation, false});
}

// One shared session (map constraints asserted once, one push/pop scope per rule) under the
// consistency semantics (a gluing failure is a break), against the enumerator.
TEST(RuleVerifier, SessionConsistencyAgreesWithEnumerator) {
  for (MapKind kind : {MapKind::GMap, MapKind::OMap}) {
    const int n = kind == MapKind::GMap ? 1 : 2;
    EncodingOptions opt;
    opt.semantics = Semantics::Consistency;
    SmtSession session({n, kind}, 4, 2, opt);
    size_t rules = 0, gluing = 0, seen = 0;
    gmr::testing::for_each_small_rule(
        n, kind, 2, kind == MapKind::GMap ? std::vector<int>{0, 1} : std::vector<int>{1, 2},
        [&](const Rule& r) {
          if (seen++ % 5) return true;
          ++rules;
          const VerifyResult s = session.verify(r);
          const VerifyResult m = verify_enum(r, 4, Semantics::Consistency);
          EXPECT_EQ(s.preserves, m.preserves) << io::rule_to_json(r).dump();
          EXPECT_EQ(s.applicable, m.applicable) << io::rule_to_json(r).dump();
          if (!s.preserves && !m.preserves) {
            EXPECT_EQ(s.counterexample->G.size(), m.counterexample->G.size());
            gluing += s.counterexample->gluing_fails;
          }
          return !::testing::Test::HasFailure();
        });
    std::printf("%s: %zu rules, %zu smallest counterexamples are gluing failures\n",
                to_string(kind), rules, gluing);
    EXPECT_GT(gluing, 0u);
  }
}
