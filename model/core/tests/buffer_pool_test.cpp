#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "model/core/buffer_pool.hpp"
#include "model/core/map.hpp"

namespace gmr {
namespace {

TEST(BufferPool, TakesTheSmallestBufferThatHoldsTheRequest) {
  give_buffer(std::vector<double>(1 << 18));  // 2 MiB
  give_buffer(std::vector<double>(1 << 19));  // 4 MiB
  const std::vector<double> v = take_buffer<double>(300000);
  EXPECT_GE(v.capacity(), size_t(1) << 19);
  EXPECT_TRUE(v.empty());
  const std::vector<double> w = take_buffer<double>(1000);
  EXPECT_GE(w.capacity(), size_t(1) << 18);
  EXPECT_LT(w.capacity(), size_t(1) << 19);
}

// A map that outlives its thread's pool (made before the pool, so destroyed after it, as a static
// map is) frees its arrays itself when destroyed; under ASan a give-back into the destroyed pool
// is reported as a use after free.
TEST(BufferPool, AMapDestroyedAfterThePoolFreesItsArrays) {
  std::thread([] {
    thread_local Map outliving(2, MapKind::GMap);  // constructed first: destroyed last
    outliving.add_darts(size_t(1) << 19);  // link arrays above the pool's 1 MiB minimum; the
                                           // pool is constructed here, after the map
    Map scratch(2, MapKind::GMap);
    scratch.add_darts(size_t(1) << 19);
  }).join();
}

}  // namespace
}  // namespace gmr
