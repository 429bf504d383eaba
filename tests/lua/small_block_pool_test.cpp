// The Lua states' small-block pool (lua/host/small_block_pool.h): classes, reuse, alignment.
#include "lua/host/small_block_pool.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <set>
#include <vector>

namespace essaim {
namespace {

TEST(SmallBlockPool, SmallMeansOneTo256Bytes) {
  EXPECT_FALSE(SmallBlockPool::IsSmall(0));
  EXPECT_TRUE(SmallBlockPool::IsSmall(1));
  EXPECT_TRUE(SmallBlockPool::IsSmall(256));
  EXPECT_FALSE(SmallBlockPool::IsSmall(257));
  EXPECT_TRUE(SmallBlockPool::SameClass(1, 16));
  EXPECT_FALSE(SmallBlockPool::SameClass(16, 17));
  EXPECT_TRUE(SmallBlockPool::SameClass(241, 256));
}

TEST(SmallBlockPool, BlocksAreDistinctAlignedAndHoldTheirSize) {
  SmallBlockPool pool;
  std::vector<std::pair<char*, size_t>> blocks;
  for (size_t size = 1; size <= 256; ++size) {
    for (int k = 0; k < 40; ++k) {  // enough to need several chunks
      auto* p = static_cast<char*>(pool.Allocate(size));
      ASSERT_NE(p, nullptr);
      EXPECT_EQ(reinterpret_cast<uintptr_t>(p) % 16, 0u);
      std::memset(p, static_cast<int>(size & 0xff), size);
      blocks.push_back({p, size});
    }
  }
  // No block overlaps another: each still holds what was written into it.
  for (auto [p, size] : blocks)
    for (size_t i = 0; i < size; ++i) ASSERT_EQ(static_cast<unsigned char>(p[i]), size & 0xff);
  for (auto [p, size] : blocks) pool.Free(p, size);
}

TEST(SmallBlockPool, FreedBlocksAreReusedWithinTheirClass) {
  SmallBlockPool pool;
  void* a = pool.Allocate(40);
  void* b = pool.Allocate(40);
  pool.Free(a, 40);
  EXPECT_EQ(pool.Allocate(33), a);  // same class (33..48): last freed, first reused
  EXPECT_NE(pool.Allocate(40), b);  // b is still in use
  pool.Free(b, 48);
  EXPECT_NE(pool.Allocate(64), b);  // another class never takes it
  EXPECT_EQ(pool.Allocate(48), b);
}

TEST(SmallBlockPool, ReleaseStartsOver) {
  SmallBlockPool pool;
  for (int i = 0; i < 10000; ++i) ASSERT_NE(pool.Allocate(100), nullptr);
  pool.Release();
  void* p = pool.Allocate(16);
  ASSERT_NE(p, nullptr);
  pool.Free(p, 16);
  EXPECT_EQ(pool.Allocate(16), p);
}

}  // namespace
}  // namespace essaim
