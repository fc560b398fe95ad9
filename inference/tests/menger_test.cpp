// Menger sponge level 1 inferred from two glued cubes (thesis §7.4.4: a lone cube does not
// represent a volume, two 3-sewn cubes do), on <0,1,2,3>: R has 20 nodes (1920 / 96 darts). The
// objects are polycubes (model/core/builders.hpp); the preserved darts are the before darts seen in
// the corner sub-cube at their own corner, with the same local dart (make_polycube lays every voxel
// out identically, 48 darts each). Each node stands for 96 darts, the hook orbit being both cubes
// (the thesis' "48 darts per node" holds for one cube only). The inferred rule, applied to another
// polycube, gives the polycube of its Menger voxels (signatures).
#include <gtest/gtest.h>

#include <map>

#include "inference/dart_mapping.hpp"
#include "inference/infer.hpp"
#include "inference/inference_format.hpp"
#include "inference/tests/inference_support.hpp"
#include "inference/tests/polycube_support.hpp"
#include "model/core/builders.hpp"
#include "model/core/orbit.hpp"
#include "model/core/signature.hpp"
#include "model/core/validity.hpp"
#include "model/scheme/scheme_engine.hpp"

using namespace gmr;
using namespace gmr::inference;
using namespace gmr::graph;
using namespace gmr::scheme;
using namespace gmr::inference::test;

using gmr::inference::test::polycube::kVoxelDarts;
using gmr::inference::test::polycube::local_corners;
using gmr::inference::test::polycube::menger_of;

TEST(RuleInference, MengerLevelOneFromTwoGluedCubes) {
  const std::vector<Voxel> cubes{{0, 0, 0}, {0, 0, 1}};
  const Map before = make_polycube(cubes);
  const std::vector<Voxel> sub = menger_of(cubes);
  const Map after = make_polycube(sub);
  ASSERT_EQ(before.size(), 96u);
  ASSERT_EQ(after.size(), 1920u);
  std::map<Voxel, Dart> voxel_index;
  for (size_t k = 0; k < sub.size(); ++k) voxel_index[sub[k]] = static_cast<Dart>(k);
  const auto corner = local_corners();
  DartMapping m;
  for (size_t k = 0; k < cubes.size(); ++k)
    for (Dart i = 0; i < kVoxelDarts; ++i) {
      const Voxel s{3 * cubes[k][0] + 2 * corner[i][0], 3 * cubes[k][1] + 2 * corner[i][1],
                    3 * cubes[k][2] + 2 * corner[i][2]};
      m.pairs.emplace_back(static_cast<Dart>(k) * kVoxelDarts + i,
                           voxel_index.at(s) * kVoxelDarts + i);
    }
  const JointGraph j = joint_from_pair(before, after, m);
  InferOptions opt;
  opt.orbit = OrbitType::range(0, 3);
  const InferenceResult res = infer_rules(j, opt);
  ASSERT_EQ(res.rules.size(), 1u) << to_text(res);
  const RuleScheme& menger = res.rules[0].scheme;
  EXPECT_EQ(menger.left.size(), 1u);
  EXPECT_EQ(menger.right.size(), 20u);
  // Applied to an L-shaped tricube: the polycube of its Menger voxels.
  const std::vector<Voxel> tri{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  auto [got, app] = scheme::apply(SchemeEngine(menger), make_polycube(tri), {0});
  ASSERT_TRUE(app.applied) << app.why;
  EXPECT_TRUE(check_validity(got).ok());
  EXPECT_EQ(got.size(), 20 * 3 * 48u);
  EXPECT_EQ(signature(got), signature(make_polycube(menger_of(tri))));
}
