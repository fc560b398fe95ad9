#include "model/core/buffer_pool.hpp"

#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "model/core/map.hpp"

namespace gmr {
namespace {

TEST(BufferPool, TakesTheSmallestBufferThatHoldsTheRequest) {
  give_buffer(std::vector<double>(1 << 18));  // 2 MiB
  give_buffer(std::vector<double>(1 << 19));  // 4 MiB
  const std::vector<double> v = take_buffer<double>(300000);
  EXPECT_GE(v.capacity(), size_t(1) << 19);
  EXPECT_TRUE(v.empty());
  const std::vector<double> w = take_buffer<double>(size_t(1) << 17);
  EXPECT_GE(w.capacity(), size_t(1) << 18);
  EXPECT_LT(w.capacity(), size_t(1) << 19);
}

// A request does not take a pooled buffer more than twice as large as it needs: a small map built
// after a large one does not keep the large one's arrays.
TEST(BufferPool, LeavesBuffersFarLargerThanTheRequest) {
  struct Link {  // a pool of its own
    uint32_t d;
  };
  std::vector<Link> large(size_t(1) << 20);  // 4 MiB
  const Link* const data = large.data();
  give_buffer(std::move(large));
  EXPECT_EQ(take_buffer<Link>(1000).capacity(), 0u);
  EXPECT_EQ(take_buffer<Link>((size_t(1) << 19) - 1).capacity(), 0u);
  EXPECT_EQ(take_buffer<Link>(size_t(1) << 19).data(), data);
}

// Tables from one page up are kept (the tables of an application on a small map are reused by the
// next one instead of going back to malloc); smaller ones are freed.
TEST(BufferPool, KeepsBuffersFromOnePageUp) {
  struct Cell {  // 32 bytes, and a pool of its own
    double v[4];
  };
  std::vector<Cell> page(128);  // 4 KiB
  const Cell* const data = page.data();
  give_buffer(std::move(page));
  EXPECT_EQ(take_buffer<Cell>(100).data(), data);
  give_buffer(std::vector<Cell>(64));  // 2 KiB
  EXPECT_EQ(take_buffer<Cell>(10).capacity(), 0u);
}

// A map's arrays and an application's scratch tables are pooled apart: scratch tables beyond their
// pool's limit do not push a map's array out, and neither kind is handed out as the other.
TEST(BufferPool, ScratchTablesAndMapStorageArePooledApart) {
  struct Slot {  // a pool of its own
    uint32_t v;
  };
  constexpr size_t n = size_t(1) << 12;
  std::vector<Slot> array(n);
  const Slot* const data = array.data();
  give_buffer(std::move(array));
  for (int k = 0; k < 40; ++k) give_buffer<Slot, ScratchTables>(std::vector<Slot>(n));
  EXPECT_EQ(take_buffer<Slot>(n).data(), data);
  EXPECT_EQ(take_buffer<Slot>(n).capacity(), 0u);
  EXPECT_GE((take_buffer<Slot, ScratchTables>(n).capacity()), n);
}

// A bitset's words come from the pool and go back to it (the dead-dart set and the markers of a
// map grow with it): the next bitset of that size reuses them, every bit reading 0.
TEST(BufferPool, ABitsetsWordsServeTheNextBitset) {
  const uint64_t* words = nullptr;
  {
    Bitset b;
    b.resize(1234567);  // a size of its own (other tests' bitsets are in the pool too)
    b.set(12345);
    words = b.data();
  }
  Bitset c;
  c.resize(1234567);
  EXPECT_EQ(c.data(), words);
  EXPECT_EQ(c.count(), 0u);
  c.set(5);
  c.resize(3000000);  // grown: the old bits kept, the new ones 0
  EXPECT_TRUE(c.test(5));
  EXPECT_EQ(c.count(), 1u);
}

// resize_for_overwrite hands out n elements: a pooled vector that held at least n is cut to n with
// its values left as they were (no fill), one that held fewer is grown with value-initialised ones.
TEST(BufferPool, ResizeForOverwriteLeavesAPooledTableUnfilled) {
  struct Entry {  // a pool of its own
    uint32_t v;
  };
  std::vector<Entry> used(5000, Entry{7});
  const Entry* const data = used.data();
  give_buffer(std::move(used));
  {
    Pooled<Entry> t;
    t.resize_for_overwrite(4000);
    ASSERT_EQ(t->data(), data);
    EXPECT_EQ(t->size(), 4000u);
    EXPECT_EQ((*t)[3999].v, 7u);  // left as the earlier use wrote it
    t->resize(2000);              // given back holding 2000
  }
  Pooled<Entry> u;
  u.resize_for_overwrite(3000);
  ASSERT_EQ(u->data(), data);
  EXPECT_EQ((*u)[1999].v, 7u);
  EXPECT_EQ((*u)[2000].v, 0u);  // beyond what it held: value-initialised
  Pooled<Entry> plain;
  plain.reserve(10);
  EXPECT_TRUE(plain->empty());  // reserve still hands out an emptied vector
}

// A map that outlives its thread's pool (made before the pool, so destroyed after it, as a static
// map is) frees its arrays itself when destroyed; under ASan a give-back into the destroyed pool
// is reported as a use after free.
TEST(BufferPool, AMapDestroyedAfterThePoolFreesItsArrays) {
  std::thread([] {
    thread_local Map outliving(2, MapKind::GMap);  // constructed first: destroyed last
    outliving.add_darts(size_t(1) << 19);          // link arrays the pool keeps; the
                                                   // pool is constructed here, after the map
    Map scratch(2, MapKind::GMap);
    scratch.add_darts(size_t(1) << 19);
  }).join();
}

}  // namespace
}  // namespace gmr
