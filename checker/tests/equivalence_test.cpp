// Empirical equivalence of the static checker (check_rule) with the semantics (semantic_verdict):
// "the rule satisfies the model's conditions" vs "every application, through every match that
// satisfies the gluing condition, on every map of the bounded family yields a map of the model".
//
// Classification of each rule:
//   agree          both verdicts equal, on an applicable rule;
//   unsound        checker OK but some application breaks the model — a checker bug; must be 0;
//   incomplete     checker FAIL but every application (there is at least one) preserves the
//                  model within the bound — a completeness gap; listed in the output;
//   vacuous        no application within the bound (L matches no map of the family, or no match
//                  satisfies the gluing condition): the semantics is vacuously "preserves", the
//                  thesis' theorems quantify over all graphs satisfying one constraint at a time
//                  and say nothing about applicability to maps. Counted separately, not compared.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <tuple>

#include "checker/check_format.hpp"
#include "checker/rule_check.hpp"
#include "checker/semantic.hpp"
#include "model/rule_io/rule_json.hpp"
#include "model/testing/rule_family.hpp"

using namespace gmr;
using namespace gmr::graph;
using namespace gmr::rewrite;
using namespace gmr::io;
using namespace gmr::testing;
using namespace gmr::checker;

namespace {

struct Stats {
  size_t rules = 0, agree_ok = 0, agree_fail = 0, unsound = 0, incomplete = 0, vacuous_ok = 0,
         vacuous_fail = 0;
  std::vector<std::string> examples;
  bool model_completion = true;
  void add(const Rule& r, const MapFamily& fam) {
    ++rules;
    const CheckReport rep = check_rule(r, model_completion);
    const SemanticVerdict v = semantic_verdict(r, fam);
    if (!v.applicable()) {
      (rep.ok() ? vacuous_ok : vacuous_fail)++;
      return;
    }
    if (rep.ok() == v.preserves) {
      (rep.ok() ? agree_ok : agree_fail)++;
      return;
    }
    std::string ex = rule_to_json(r).dump() + "\n  checker: " + to_text(rep);
    if (rep.ok()) {
      ++unsound;
      ex = "UNSOUND " + ex + "  semantics: " + to_text(*v.witness, r, fam);
    } else {
      ++incomplete;
      ex = "INCOMPLETE " + ex + "  semantics: preserves on " + std::to_string(v.applications) +
           " applications";
    }
    if (examples.size() < 8) examples.push_back(ex);
  }
  std::string summary(const std::string& what) const {
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "%s: %zu rules; agree ok %zu, agree fail %zu, unsound %zu, incomplete %zu, "
                  "vacuous (checker ok %zu, "
                  "checker fail %zu)",
                  what.c_str(), rules, agree_ok, agree_fail, unsound, incomplete, vacuous_ok,
                  vacuous_fail);
    return buf;
  }
};

void report(const Stats& s, const std::string& what) {
  std::printf("%s\n", s.summary(what).c_str());
  for (const auto& e : s.examples) std::printf("  %s\n", e.c_str());
  ::testing::Test::RecordProperty(what, s.summary(what));
}

// Every rule of at most 2 nodes with arcs of `labels` against every map of at most 4 darts of the
// model (`model` names it in the report): no unsound and no incomplete verdict of the checker.
void expect_equivalent_up_to_2_nodes(int n, MapKind kind, const std::vector<int>& labels,
                                     const std::string& model) {
  const MapFamily fam = map_family(n, kind, 4);
  Stats s;
  for_each_small_rule(n, kind, 2, labels, [&](const Rule& r) {
    s.add(r, fam);
    return true;
  });
  EXPECT_EQ(s.incomplete, 0u);
  std::string label_set;
  for (int i : labels) label_set += (label_set.empty() ? "" : ",") + std::to_string(i);
  report(s, model + ", all rules <= 2 nodes, labels {" + label_set + "}, maps <= 4 darts (" +
                std::to_string(fam.maps.size()) + ")");
  EXPECT_EQ(s.unsound, 0u);
}

}  // namespace

TEST(Equivalence, AllRulesUpTo2Nodes_1GMaps) {
  expect_equivalent_up_to_2_nodes(1, MapKind::GMap, {0, 1}, "1-G-maps");
}

TEST(Equivalence, AllRulesUpTo2Nodes_2GMaps) {
  expect_equivalent_up_to_2_nodes(2, MapKind::GMap, {0, 1, 2}, "2-G-maps");
}

TEST(Equivalence, AllRulesUpTo2Nodes_2OMaps) {
  expect_equivalent_up_to_2_nodes(2, MapKind::OMap, {1, 2}, "2-O-maps");
}

TEST(Equivalence, MapFamilySizes) {
  for (size_t k = 1; k <= 6; ++k)
    std::printf("connected 2-G-maps with %zu darts: %zu; 2-O-maps: %zu; 1-G-maps: %zu\n", k,
                connected_maps(2, MapKind::GMap, k).size(),
                connected_maps(2, MapKind::OMap, k).size(),
                connected_maps(1, MapKind::GMap, k).size());
}

// The thesis' per-constraint reading of C_r (ij-completion only, no O-completion of L) is not
// complete at the model level: rules whose L has an arc of an involutive dimension without its
// reverse are rejected although they preserve G-maps (e.g. L = {a-0-b, b-2->a}, R = {0-loops on
// a and b, b-2->a}: in a G-map the unmatched a-2->b closes the 0202-cycles). This test pins the
// gap: with model completion (the default) there are no incomplete verdicts (test above).
TEST(Equivalence, PerConstraintCycleConditionIsIncompleteOnGMaps) {
  const MapFamily fam = map_family(2, MapKind::GMap, 4);
  Stats s;
  s.model_completion = false;
  for_each_small_rule(2, MapKind::GMap, 2, {0, 2}, [&](const Rule& r) {
    s.add(r, fam);
    return true;
  });
  report(s, "2-G-maps WITHOUT model completion, rules <= 2 nodes, labels {0,2}");
  EXPECT_EQ(s.unsound, 0u);
  EXPECT_GT(s.incomplete, 0u);
}

TEST(Equivalence, RandomLargerRules) {
  std::mt19937_64 rng(20240603);
  for (auto [n, kind, darts] :
       {std::tuple{1, MapKind::GMap, size_t{6}}, std::tuple{2, MapKind::GMap, size_t{5}},
        std::tuple{2, MapKind::OMap, size_t{5}}, std::tuple{3, MapKind::GMap, size_t{4}},
        std::tuple{3, MapKind::OMap, size_t{4}}}) {
    const MapFamily fam = map_family(n, kind, darts);
    Stats s;
    for (int k = 0; k < 3000; ++k) s.add(random_rule_from_maps(rng, fam, 5), fam);
    report(s, std::string("random rules <= 5+2 nodes, ") + std::to_string(n) + "-" +
                  to_string(kind) + ", maps <= " + std::to_string(darts) + " darts (" +
                  std::to_string(fam.maps.size()) + " maps)");
    EXPECT_EQ(s.unsound, 0u);
    EXPECT_EQ(s.incomplete, 0u);
  }
}
