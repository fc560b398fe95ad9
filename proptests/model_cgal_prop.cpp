// Signature equality <=> isomorphism, checked against CGAL's Generalized_map::is_isomorphic_to
// (an independent implementation, test-only) on a sample of random pairs: a random map,
// and a relabeled copy of it after one random re-gluing (isomorphic or not: the hard cases),
// for G-maps of dimensions 1, 2, 3 from every generator family.
#include <gtest/gtest.h>

#include "model/core/tests/cgal_diff.hpp"
#include "proptests/generators.hpp"
#include "proptests/harness.hpp"

using namespace gmr;
using namespace gmr::testing;
using namespace gmr::prop;

namespace {

template <unsigned N>
bool cgal_verdict(const Map& g, const Map& h) {
  cgal_diff::CMap<N> cg, ch;
  cgal_diff::to_cgal<N>(g, cg);
  cgal_diff::to_cgal<N>(h, ch);
  return cgal_diff::cgal_isomorphic<N>(cg, ch);
}

bool cgal_iso(const Map& g, const Map& h) {
  switch (g.dimension()) {
    case 1:
      return cgal_verdict<1>(g, h);
    case 2:
      return cgal_verdict<2>(g, h);
    case 3:
      return cgal_verdict<3>(g, h);
  }
  throw std::logic_error("dimension");
}

}  // namespace

TEST(ModelCgalProps, SignatureEqualityIsCgalIsomorphism) {
  EXPECT_TRUE(check_property<MapCase>("signature_vs_cgal", gen_map_case(4), [](const MapCase& c) {
    const Map g = c.build();
    Map m = g;
    Rng rng(c.seed * 1000003 + 11);
    const Mutation mu =
        *rc::gen::arbitrary<bool>() ? resew_one_link(m, rng) : mutate_one_link(m, rng);
    const Map h = permute_darts(m, *gen_permutation(m.capacity()));
    const bool ours = signature(g) == signature(h);
    const bool theirs = cgal_iso(g, h);
    RC_TAG(theirs ? "isomorphic" : "not isomorphic");
    RC_LOG() << "edit: " << mu.str() << "\n";
    RC_ASSERT(ours == theirs);
    RC_ASSERT(is_isomorphic(g, h) == theirs);
  }));
}
