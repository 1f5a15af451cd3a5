// PairBlocks (neighbor/pair_blocks.hpp): the structure behind the race-free, thread-count
// independent pair loop.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "neighbor/pair_blocks.hpp"
#include "neighbor/verlet_list.hpp"

namespace mpdem {
namespace {

// A random dense cloud of n spheres, radii 1-5 mm, 3000 in an 80 mm cube (the same density
// for any n).
VerletList random_list(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  const double side = 0.08 * std::cbrt(static_cast<double>(n) / 3000.0);
  std::uniform_real_distribution<double> u(0.0, side), rr(1e-3, 5e-3);
  std::vector<Vec3> x(n);
  std::vector<double> r(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = {u(rng), u(rng), u(rng)};
    r[i] = rr(rng);
  }
  VerletList list;
  list.build(x, r, 1e-4);
  return list;
}

TEST(PairBlocks, BlockSizeIsAPowerOfTwoSetByTheParticleCountAlone) {
  EXPECT_EQ(PairBlocks::block_size(0), PairBlocks::kMinBlock);
  EXPECT_EQ(PairBlocks::block_size(100), PairBlocks::kMinBlock);
  EXPECT_EQ(PairBlocks::block_size(20000), 2048u);  // 20000 / 8 = 2500: 10 blocks, not 5 of 4096
  EXPECT_EQ(PairBlocks::block_size(30000), 2048u);
  EXPECT_EQ(PairBlocks::block_size(50000), PairBlocks::kMaxBlock);
  EXPECT_EQ(PairBlocks::block_size(100000), PairBlocks::kMaxBlock);
  EXPECT_EQ(PairBlocks::block_size(10000000), PairBlocks::kMaxBlock);
  for (std::size_t n = 1; n < 200000; n = n * 3 / 2 + 1) {
    const std::size_t b = PairBlocks::block_size(n);
    EXPECT_TRUE(b >= PairBlocks::kMinBlock && b <= PairBlocks::kMaxBlock && (b & (b - 1)) == 0) << n;
    // As many blocks as wanted, unless a bound stops it.
    const std::size_t blocks = (n + b - 1) / b;
    EXPECT_TRUE(blocks >= PairBlocks::kTargetBlocks || b == PairBlocks::kMinBlock) << n;
    EXPECT_TRUE(blocks < 2 * PairBlocks::kTargetBlocks + 1 || b == PairBlocks::kMaxBlock) << n;
  }
}

TEST(PairBlocks, CrossPairsAreNumberedInSlotOrderAndListedAtTheirSecondMember) {
  const std::size_t n = 40 * PairBlocks::kMinBlock + PairBlocks::kMinBlock / 2;  // the last block partial
  const std::size_t block = PairBlocks::block_size(n);
  ASSERT_EQ(block, 4 * PairBlocks::kMinBlock);
  const VerletList list = random_list(n, 3);
  PairBlocks blocks;
  blocks.build(list);
  ASSERT_EQ(blocks.block(), block);
  ASSERT_EQ(blocks.num_blocks(), (n + block - 1) / block);
  const auto& off = list.offsets();
  const auto& idx = list.indices();

  // Expected: cross pairs in slot order, numbered from 0; per block the count.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> cross;  // (first, second) by cross index
  std::vector<std::size_t> per_block(blocks.num_blocks(), 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t end = (i / block + 1) * block;
    ASSERT_EQ(blocks.block_end(i), std::min(end, n));
    bool seen_cross = false;
    for (std::size_t k = off[i]; k < off[i + 1]; ++k) {
      const bool is_cross = idx[k] >= end;
      EXPECT_TRUE(!seen_cross || is_cross) << "cross slots must be the tail of a particle's range";
      seen_cross = seen_cross || is_cross;
      if (is_cross) {
        cross.emplace_back(static_cast<std::uint32_t>(i), idx[k]);
        ++per_block[i / block];
      }
    }
  }
  ASSERT_GT(cross.size(), 100u) << "the test needs cross pairs";
  ASSERT_EQ(blocks.num_cross(), cross.size());
  std::size_t base = 0;
  for (std::size_t b = 0; b < blocks.num_blocks(); ++b) {
    EXPECT_EQ(blocks.cross_base(b), base);
    base += per_block[b];
  }

  // Each cross index appears exactly once, at its second member, ascending per member; every
  // slot knows its first member.
  std::vector<int> seen(cross.size(), 0);
  const auto& members = blocks.cross_particles();
  for (std::size_t m = 0; m < members.size(); ++m) {
    EXPECT_TRUE(m == 0 || members[m - 1] < members[m]);
    long last = -1;
    for (std::uint32_t c : blocks.entries(m)) {
      ASSERT_LT(c, cross.size());
      EXPECT_EQ(cross[c].second, members[m]);
      EXPECT_GT(static_cast<long>(c), last);
      last = static_cast<long>(c);
      ++seen[c];
    }
  }
  for (std::size_t c = 0; c < cross.size(); ++c) EXPECT_EQ(seen[c], 1) << c;
  const auto& first = blocks.first_members();
  ASSERT_EQ(first.size(), idx.size());
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = off[i]; k < off[i + 1]; ++k) ASSERT_EQ(first[k], i) << k;
}

TEST(PairBlocks, SmallSetsHaveNoCrossPairs) {
  const VerletList list = random_list(500, 5);  // one block
  PairBlocks blocks;
  blocks.build(list);
  EXPECT_EQ(blocks.num_blocks(), 1u);
  EXPECT_EQ(blocks.num_cross(), 0u);
  EXPECT_TRUE(blocks.cross_particles().empty());
}

}  // namespace
}  // namespace mpdem
