// counts_to_offsets: per-row counts into 32-bit CSR offsets, refusing totals beyond 2^32 - 1.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "neighbor/csr_offsets.hpp"

namespace mpdem {
namespace {

TEST(CsrOffsets, ScansCountsIntoOffsets) {
  std::vector<std::uint32_t> offset{0, 3, 0, 5, 1};
  const auto total = counts_to_offsets(offset);
  ASSERT_TRUE(total.has_value());
  EXPECT_EQ(*total, 9u);
  EXPECT_EQ(offset, (std::vector<std::uint32_t>{0, 3, 3, 8, 9}));
  std::vector<std::uint32_t> empty{0};
  EXPECT_EQ(counts_to_offsets(empty), 0u);
}

TEST(CsrOffsets, RefusesATotalBeyondThirtyTwoBits) {
  const std::uint32_t big = 0xFFFFFFFFu;
  std::vector<std::uint32_t> exact{0, big - 1, 1};  // 2^32 - 1 entries still fit
  EXPECT_EQ(counts_to_offsets(exact), std::size_t{big});
  std::vector<std::uint32_t> over{0, big, 1};
  EXPECT_FALSE(counts_to_offsets(over).has_value());
}

}  // namespace
}  // namespace mpdem
