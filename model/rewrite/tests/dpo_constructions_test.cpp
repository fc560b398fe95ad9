// The two constructions of a direct derivation (categorical pushout complement + pushout, and
// in-place rewriting) give the same H with the same comatch, and so do the two map paths
// (through D-graphs, and directly on the links), on every application of many generated rules
// on every small map.
#include <gtest/gtest.h>

#include <random>

#include "checker/semantic.hpp"
#include "model/core/error.hpp"
#include "model/core/signature.hpp"
#include "model/rewrite/dpo.hpp"
#include "model/testing/rule_family.hpp"

using namespace gmr;
using namespace gmr::graph;
using namespace gmr::rewrite;
using namespace gmr::testing;

TEST(DpoConstructions, CategoricalEqualsInPlaceOnEveryApplication) {
  std::mt19937_64 rng(7);
  size_t applications = 0, map_results = 0;
  for (auto [n, kind] :
       {std::pair{1, MapKind::GMap}, std::pair{2, MapKind::GMap}, std::pair{2, MapKind::OMap}}) {
    const MapFamily fam = map_family(n, kind, 4);
    for (int k = 0; k < 300; ++k) {
      const Rule r = random_rule_from_maps(rng, fam, 4);
      for (size_t g = 0; g < fam.graphs.size(); ++g) {
        for (const Match& m : find_matches(r.left(), fam.graphs[g], 50)) {
          if (!satisfies_gluing(r, fam.graphs[g], m)) continue;
          ++applications;
          const Derivation a = derive(r, fam.graphs[g], m),
                           b = derive(r, fam.graphs[g], m, Construction::Rewriting);
          std::string why;
          ASSERT_TRUE(same_derivation(a, b, &why)) << why;
          EXPECT_EQ(a.D.num_nodes(), fam.graphs[g].num_nodes() - r.deleted_nodes().size());
          // On maps: both paths agree whenever H is a map (else both refuse).
          std::vector<Dart> md;
          for (graph::Node v : m.node) md.push_back(graph::dart_of(v));
          bool ok1 = true, ok2 = true;
          MapDerivation x, y;
          try {
            x = apply(r, fam.maps[g], md, Construction::Rewriting);
          } catch (const Error&) {
            ok1 = false;
          }
          try {
            y = apply(r, fam.maps[g], md, Construction::Categorical);
          } catch (const Error&) {
            ok2 = false;
          }
          ASSERT_EQ(ok1, ok2);
          if (ok1) {
            ++map_results;
            EXPECT_TRUE(is_isomorphic(x.H, y.H));
            EXPECT_EQ(x.H.size(), y.H.size());
          }
        }
      }
    }
  }
  std::printf("%zu applications compared, %zu with a map result\n", applications, map_results);
  EXPECT_GT(applications, 1000u);
  EXPECT_GT(map_results, 100u);
}
