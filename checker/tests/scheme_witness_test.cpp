// Rejected schemes: a bounded search for a G-map on which an application breaks validity (the
// checker's C_S is only sufficient, Theorem 6, so a rejected scheme may also be harmless; the
// search shows which). Bound: the polycubes below (up to 4 voxels), every dart as hook.
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <optional>

#include "checker/scheme_checker.hpp"
#include "model/core/builders.hpp"
#include "model/core/validity.hpp"
#include "model/rule_io/jme_import.hpp"
#include "model/scheme/scheme_engine.hpp"
#include "model/testing/source_tree.hpp"

using namespace gmr;
using namespace gmr::scheme;
using namespace gmr::io;
using namespace gmr::checker;

namespace {

struct Witness {
  std::string object;
  Dart hook;
  std::string violation;
};

std::optional<Witness> find_witness(const RuleScheme& s) {
  const std::vector<std::pair<std::string, std::vector<Voxel>>> objects = {
      {"cube", {{0, 0, 0}}},
      {"2 cubes", {{0, 0, 0}, {1, 0, 0}}},
      {"L-tricube", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}},
      {"2x2 cubes around an edge", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}},
  };
  SchemeEngine e(s);
  if (s.hooks.size() != 1) return std::nullopt;
  for (const auto& [name, voxels] : objects) {
    const Map g = make_polycube(voxels);
    for (Dart d : g.darts()) {
      Map h = g;
      SchemeApplication a = scheme::apply(e, h, {d});
      if (!a.applied) continue;
      ValidityReport v = check_validity(h, 1);
      if (!v.ok()) return Witness{name, d, to_text(v.violations.front())};
    }
  }
  return std::nullopt;
}

}  // namespace

TEST(SchemeWitness, RejectedJerboaRules) {
  JmeModeler m =
      read_jme_file(gmr::testing::source_path("tools/data/jerboa/JerboaTrackingOrbit.jme"));
  std::map<std::string, std::optional<Witness>> found;
  SchemeCheckOptions topology;  // witnesses are about the topology
  topology.embeddings = false;
  for (const RuleScheme& s : m.rules) {
    if (check_scheme(s, topology).ok()) continue;
    SchemeEngine e(s);
    if (!e.not_combinatorial().empty()) continue;  // never applicable (I_S fails)
    found[s.name] = find_witness(s);
    if (found[s.name])
      std::cout << s.name << ": breaks on " << found[s.name]->object << " at dart "
                << found[s.name]->hook << ": " << found[s.name]->violation << "\n";
    else
      std::cout << s.name << ": no witness within the bound\n";
  }
  // The three rules rejected for C-cycle-word (E11) and applicable by the engine. DeleteEdge and
  // MergeEdge2 break the cycle constraint within the bound; MergeFacesAroundVertex has no witness
  // on these polycubes (the condition is only sufficient, or the bound is too small).
  ASSERT_EQ(found.size(), 3u);
  EXPECT_TRUE(found["DeleteEdge"].has_value());
  EXPECT_TRUE(found["MergeEdge2"].has_value());
  EXPECT_FALSE(found["MergeFacesAroundVertex"].has_value());
}

TEST(SchemeWitness, AcceptedLibrarySchemesHaveNone) {
  // Sanity check of the search itself: an accepted 3D scheme yields no witness.
  RuleScheme unsew;
  unsew.name = "unsew3";
  unsew.dimension = 3;
  unsew.orbit = OrbitType{0, 1};
  for (auto* g : {&unsew.left, &unsew.right}) {
    g->add_node("n0", OrbitType{0, 1});
    g->add_node("n1", OrbitType{0, 1});
  }
  unsew.left.add_arc("n0", "n1", 3);
  unsew.right.add_arc("n0", "n0", 3);
  unsew.right.add_arc("n1", "n1", 3);
  unsew.hooks = {"n0"};
  ASSERT_TRUE(check_scheme(unsew).ok());
  EXPECT_FALSE(find_witness(unsew).has_value());
}
