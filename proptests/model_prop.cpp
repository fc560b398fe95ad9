// Properties of the model: generated maps are valid; validity locates every broken
// constraint (checked against the independent D-graph constraint checker); orbits are closed and
// partition the darts; signatures are invariant under relabeling and separate non-isomorphic maps;
// JSON round trips preserve the map.
#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "model/core/orbit.hpp"
#include "model/core/position.hpp"
#include "model/core/signature.hpp"
#include "model/core/validity.hpp"
#include "model/graph/constraints.hpp"
#include "model/graph/dgraph.hpp"
#include "model/map_io/map_json.hpp"
#include "model/map_io/off.hpp"
#include "proptests/generators.hpp"
#include "proptests/harness.hpp"

using namespace gmr;
using namespace gmr::graph;
using namespace gmr::io;
using namespace gmr::testing;
using namespace gmr::prop;

namespace {

// A random relabeling of the darts of g keeps its signature and is isomorphic to it.
void assert_relabeling_invariant(const Map& g) {
  const Map h = permute_darts(g, *gen_permutation(g.capacity()));
  RC_ASSERT(signature(g) == signature(h));
  RC_ASSERT(is_isomorphic(g, h));
}

}  // namespace

TEST(ModelProps, GeneratedMapsAreValid) {
  EXPECT_TRUE(check_property<MapCase>("generated_valid", gen_map_case(), [](const MapCase& c) {
    const Map g = c.build();
    RC_ASSERT(g.size() > 0u);
    RC_ASSERT(check_validity(g).ok());
    RC_ASSERT(check_map_constraints(to_dgraph(g), g.dimension(), g.kind()).empty());
  }));
}

// The set of (kind, dart, dims) reported by check_validity equals the one found by the D-graph
// checker (constraints.cpp, a separate implementation over arc lists), after a random raw write.
TEST(ModelProps, ValidityLocatesEveryBrokenConstraint) {
  EXPECT_TRUE(check_property<MapCase>("validity_locates", gen_map_case(4), [](const MapCase& c) {
    Map g = c.build();
    const auto darts = g.darts();
    const Dart d = darts[*rc::gen::inRange<size_t>(0, darts.size())];
    const Dart e = darts[*rc::gen::inRange<size_t>(0, darts.size())];
    const int i = *rc::gen::inRange(0, g.dimension() + 1);
    const bool symmetric = *rc::gen::arbitrary<bool>();
    const Dart old = g.alpha(i, d);
    if (symmetric) {  // keeps alpha_i an involution: only cycle constraints can break
      g.unlink(i, d);
      g.unlink(i, e);
      g.link(i, d, e);
    } else {
      g.set_alpha(i, d, e);
    }
    const auto report = check_validity(g, SIZE_MAX);
    std::set<std::tuple<int, Dart, int, int>> mine, theirs;
    for (const auto& v : report.violations) {
      const int kind = v.constraint == Constraint::Cycle ? 2 : 1;
      mine.insert({kind, v.at, v.i, v.j});
    }
    const DGraph dg = to_dgraph(g);
    for (const auto& v : check_map_constraints(dg, g.dimension(), g.kind())) {
      if (v.constraint == Constraint::Cycle) theirs.insert({2, v.at, v.i, v.j});
      // Non-orientation at the arc's source is the involution failure at that dart; incident-arc
      // failures (two incoming arcs) come with it and are folded into the same violation.
      if (v.constraint == Constraint::NonOrientation && v.path.size() == 2 && v.path[0] == v.at)
        theirs.insert({1, v.at, v.i, -1});
    }
    RC_ASSERT(mine == theirs);
    if (!symmetric && e != old && (e != d || old != d)) {
      // The written dart (or its abandoned partner) is named.
      bool named = false;
      for (const auto& v : report.violations)
        if (v.constraint == Constraint::NonOrientation && v.i == i && (v.at == d || v.at == old))
          named = true;
      RC_ASSERT(named);
    }
  }));
}

TEST(ModelProps, OrbitsPartitionTheDarts) {
  EXPECT_TRUE(check_property<MapCase>("orbits_partition", gen_map_case(), [](const MapCase& c) {
    const Map g = c.build();
    const OrbitType o = *gen_orbit_type(g.dimension());
    std::vector<int> owner(g.capacity(), -1);
    int k = 0;
    for (Dart rep : orbit_representatives(g, o)) {
      const auto orb = orbit(g, o, rep);
      RC_ASSERT(orb.front() == rep);
      for (Dart x : orb) {
        RC_ASSERT(owner[x] == -1);
        owner[x] = k;
        for (int i : o.dims())
          RC_ASSERT(std::find(orb.begin(), orb.end(), g.alpha(i, x)) != orb.end());
      }
      ++k;
    }
    for (Dart x : g.darts()) RC_ASSERT(owner[x] != -1);
    RC_ASSERT(static_cast<size_t>(k) == count_orbits(g, o));
  }));
}

TEST(ModelProps, SignatureInvariantUnderRelabeling) {
  EXPECT_TRUE(check_property<MapCase>("signature_relabel", gen_map_case(4), [](const MapCase& c) {
    const Map g = c.build();
    assert_relabeling_invariant(g);
  }));
}

TEST(ModelProps, OneLinkChangeBreaksIsomorphism) {
  EXPECT_TRUE(check_property<MapCase>("signature_mutation", gen_map_case(4), [](const MapCase& c) {
    const Map g = c.build();
    Map h = g;
    Rng rng(c.seed ^ 0x9e3779b97f4a7c15ull);
    const Mutation m = mutate_one_link(h, rng);
    RC_PRE(m.kind != Mutation::Kind::None);
    RC_ASSERT(is_valid(h));
    RC_ASSERT(!is_isomorphic(g, h));
    RC_ASSERT(signature(g) != signature(h));
  }));
}

TEST(ModelProps, SignatureEqualityIsIsomorphism) {
  EXPECT_TRUE(check_property<MapCase>("signature_iff_iso", gen_map_case(4), [](const MapCase& c) {
    const Map g = c.build();
    Map h = g;
    Rng rng(c.seed * 31 + 7);
    resew_one_link(h, rng);
    const Map hp = permute_darts(h, *gen_permutation(h.capacity()));
    RC_ASSERT(is_isomorphic(g, hp) == (signature(g) == signature(hp)));
  }));
}

TEST(ModelProps, JsonRoundTrip) {
  EXPECT_TRUE(check_property<MapCase>("json_roundtrip", gen_map_case(), [](const MapCase& c) {
    const Map g = c.build();
    const EmbeddedMap f = read_map_json(write_map_json(g, {}));
    RC_ASSERT(f.map.dimension() == g.dimension());
    RC_ASSERT(f.map.size() == g.size());
    RC_ASSERT(is_isomorphic(g, f.map));
    RC_ASSERT(signature(g) == signature(f.map));
  }));
}

// --- O-maps (Def. 32) ----------------------------------------------------------------------

TEST(ModelProps, GeneratedOMapsAreValid) {
  EXPECT_TRUE(
      check_property<MapCase>("omap_generated_valid", gen_omap_case(), [](const MapCase& c) {
        const Map g = c.build();
        RC_TAG(to_string(c.family));
        RC_ASSERT(g.is_omap());
        RC_ASSERT(check_validity(g).ok());
        RC_ASSERT(check_map_constraints(to_dgraph(g), g.dimension(), g.kind()).empty());
      }));
}

TEST(ModelProps, OMapSignatureRelabelAndJsonRoundTrip) {
  EXPECT_TRUE(
      check_property<MapCase>("omap_signature_json", gen_omap_case(4), [](const MapCase& c) {
        const Map g = c.build();
        assert_relabeling_invariant(g);
        const EmbeddedMap f = read_map_json(write_map_json(g, {}));
        RC_ASSERT(f.map.is_omap());
        RC_ASSERT(is_isomorphic(g, f.map));
        // Swapping the beta_1 images of two darts keeps a valid 2-O-map (beta_1 stays a
        // permutation, no cycle constraint for n = 2); isomorphic or not, signature equality must
        // agree with is_isomorphic.
        if (g.dimension() == 2 && g.size() >= 2) {
          Map m = g;
          const auto darts = m.darts();
          const Dart a = darts[*rc::gen::inRange<size_t>(0, darts.size())];
          const Dart b = darts[*rc::gen::inRange<size_t>(0, darts.size())];
          const Dart fa = m.alpha(1, a), fb = m.alpha(1, b);
          m.set_alpha(1, a, fb);
          m.set_alpha(1, b, fa);
          RC_ASSERT(is_valid(m));
          RC_ASSERT(is_isomorphic(g, m) == (signature(g) == signature(m)));
        }
      }));
}

// --- OFF round trip --------------------------------------------------------------------------

// A 2-G-map whose faces are polygons with >= 3 sides, given distinct positions per vertex, written
// as OFF and read back: the same map up to isomorphism, and every vertex keeps its position. Maps
// OFF cannot describe (a face through one vertex twice, pinched vertices, non-manifold edges) are
// refused by the writer or the reader with an Error: discarded, and counted by RC_TAG.
TEST(ModelProps, OffRoundTrip) {
  EXPECT_TRUE(
      check_property<MapCase>("off_roundtrip", gen_map_case_of_dim(2, 6), [](const MapCase& c) {
        const Map g = c.build();
        PositionEmbedding pos(kPositionName, OrbitType{1, 2});
        double k = 0;
        for (Dart rep : orbit_representatives(g, OrbitType{1, 2})) {
          pos.set(g, rep, Vec3{k, k * k, 1.0 / (k + 1)});
          k += 1;
        }
        std::string text;
        try {
          text = write_off(g, pos);
        } catch (const Error& e) {
          RC_TAG("not OFF-writable");
          RC_DISCARD(e.what());
        }
        EmbeddedMap back;
        try {
          back = read_off(text, "roundtrip.off");
        } catch (const Error& e) {
          RC_TAG("not OFF-readable (pinched)");
          RC_DISCARD(e.what());
        }
        RC_TAG("round trip");
        RC_ASSERT(is_isomorphic(g, back.map));
        // Positions: the multiset of vertex positions is the same.
        std::multiset<Vec3> pg, pb;
        for (Dart rep : orbit_representatives(g, OrbitType{1, 2})) pg.insert(pos.get(rep));
        for (Dart rep : orbit_representatives(back.map, OrbitType{1, 2})) {
          pb.insert(back.position().get(rep));
        }
        RC_ASSERT(pg == pb);
      }));
}
