// RebuildHeapPolicy: a rare rebuild's large blocks come from mappings of their own (returned to
// the system when freed), a frequent rebuild's from the heap.
#include <gtest/gtest.h>

#include <cstdlib>

#include "core/heap_policy.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace mpdem {
namespace {

TEST(RebuildHeapPolicy, FirstAndLateRebuildsAreRareFrequentOnesAreNot) {
  RebuildHeapPolicy h;
  EXPECT_TRUE(h.rare());  // the first build
  h.before_rebuild();
  for (std::uint64_t k = 1; k < RebuildHeapPolicy::kRareAfterSteps; ++k) h.step();
  EXPECT_FALSE(h.rare());  // one step short
  h.step();
  EXPECT_TRUE(h.rare());
  h.before_rebuild();
  h.step();
  EXPECT_FALSE(h.rare());  // counted from the last rebuild
}

#if defined(__GLIBC__)
// Mapped blocks glibc holds (mallinfo2().hblks) while a 1 MiB block is alive.
std::size_t mapped_blocks_with_a_block() {
  // Through a volatile pointer: the compiler may drop a new/delete pair whose memory is unused.
  void* (*volatile allocate)(std::size_t) = std::malloc;
  void* block = allocate(std::size_t{1} << 20);
  const std::size_t mapped = mallinfo2().hblks;
  std::free(block);
  return mapped;
}

TEST(RebuildHeapPolicy, RareRebuildsMapTheirBlocksFrequentOnesUseTheHeap) {
  if (!heap_policy_active()) GTEST_SKIP() << "the policy is off: a sanitizer's allocator or MALLOC_MMAP_THRESHOLD_";
  RebuildHeapPolicy h;
  const std::size_t before = mallinfo2().hblks;
  ASSERT_EQ(h.before_rebuild(), RebuildHeapPolicy::kRareThreshold);  // the first build: rare
  EXPECT_EQ(mapped_blocks_with_a_block(), before + 1);
  h.step();
  ASSERT_EQ(h.before_rebuild(), RebuildHeapPolicy::kFrequentThreshold);
  EXPECT_EQ(mapped_blocks_with_a_block(), before);
}
#endif

}  // namespace
}  // namespace mpdem
