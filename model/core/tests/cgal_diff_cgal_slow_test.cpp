// The larger sweep of the CGAL differential test (label slow): more seeds and bigger maps than
// cgal_diff_cgal_test.cpp, same comparisons (see cgal_diff.hpp: compare_one).
// GMR_CGAL_DIFF_SEEDS (environment) overrides the number of seeds per family (default 400).
#include <cstdlib>

#include "model/core/tests/cgal_diff.hpp"

using namespace gmr;
using namespace gmr::testing;

using namespace cgal_diff;
using gmr::testing::Rng;

namespace {

uint64_t seeds() {
  const char* s = std::getenv("GMR_CGAL_DIFF_SEEDS");
  return s ? std::strtoull(s, nullptr, 10) : 400;
}

template <unsigned N, class Make>
void sweep(const char* what, uint64_t salt, Make&& make) {
  Stats st;
  const uint64_t k = seeds();
  for (uint64_t s = 0; s < k; ++s) {
    Rng rng(s * 104729 + salt);
    const Map g = make(rng);
    SCOPED_TRACE(std::string(what) + " seed=" + std::to_string(s));
    compare_one<N>(g, rng, st);
    if (::testing::Test::HasFatalFailure()) break;
  }
  std::cout << "[cgal-diff slow] " << what << ": " << st.str() << "\n";
}

}  // namespace

TEST(CgalDiffSlow, GluedPolygons) {
  sweep<2>("glued polygons n=2", 1, [](Rng& rng) {
    gmr::testing::GluedPolygonsOptions o;
    o.max_faces = 40;
    o.max_sides = 8;
    o.max_extra_sews = 40;
    o.connected = gmr::testing::chance(rng, 80);
    return gmr::testing::random_glued_polygons(rng, o);
  });
  sweep<3>("glued polygons n=3", 2, [](Rng& rng) {
    gmr::testing::GluedPolygonsOptions o;
    o.n = 3;
    o.max_faces = 30;
    o.max_extra_sews = 30;
    return gmr::testing::random_glued_polygons(rng, o);
  });
}

TEST(CgalDiffSlow, Polycubes) {
  sweep<3>("polycubes n=3", 3, [](Rng& rng) {
    gmr::testing::PolycubeOptions o;
    o.max_voxels = 24;
    return gmr::testing::random_polycube(rng, o);
  });
}

TEST(CgalDiffSlow, SewSequences) {
  sweep<2>("sew sequences n=2", 4, [](Rng& rng) {
    gmr::testing::SewSequenceOptions o;
    o.max_cells = 16;
    o.steps = 80;
    return gmr::testing::random_sewn_cells(rng, o);
  });
  sweep<3>("sew sequences n=3", 5, [](Rng& rng) {
    gmr::testing::SewSequenceOptions o;
    o.n = 3;
    o.max_cells = 16;
    o.steps = 80;
    return gmr::testing::random_sewn_cells(rng, o);
  });
  sweep<4>("sew sequences n=4", 6, [](Rng& rng) {
    gmr::testing::SewSequenceOptions o;
    o.n = 4;
    o.max_cells = 10;
    o.steps = 60;
    return gmr::testing::random_sewn_cells(rng, o);
  });
}
