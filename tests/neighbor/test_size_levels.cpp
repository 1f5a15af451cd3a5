// Size levels (neighbor/size_levels.hpp): levels by powers of two of R / R_min, exact at the
// boundaries, one level for narrow distributions.
#include <gtest/gtest.h>

#include <vector>

#include "neighbor/size_levels.hpp"

namespace mpdem {
namespace {

TEST(SizeLevels, BinsRadiiByPowersOfTwoOfTheSmallest) {
  const std::vector<double> r{1e-3, 1.5e-3, 2e-3, 3.9e-3, 4e-3, 20e-3, 1e-3};
  const SizeLevels s = size_levels(r);
  EXPECT_EQ(s.r_min, 1e-3);
  ASSERT_EQ(s.count(), 5u);  // 1, 2, 4, 8 (empty), 16 R_min
  EXPECT_EQ(s.level, (std::vector<std::uint8_t>{0, 0, 1, 1, 2, 4, 0}));
  EXPECT_EQ(s.r_max, (std::vector<double>{1.5e-3, 3.9e-3, 4e-3, 0.0, 20e-3}));
  EXPECT_EQ(s.finest_r_max(), 1.5e-3);
}

TEST(SizeLevels, OneLevelBelowAFactorTwoOrWithAZeroRadius) {
  const SizeLevels narrow = size_levels(std::vector<double>{1e-3, 1.999e-3, 1.2e-3});
  EXPECT_EQ(narrow.count(), 1u);
  EXPECT_TRUE(narrow.level.empty());
  EXPECT_EQ(narrow.finest_r_max(), 1.999e-3);
  const SizeLevels zero = size_levels(std::vector<double>{0.0, 1e-3, 5e-2});
  EXPECT_EQ(zero.count(), 1u);
  EXPECT_EQ(zero.finest_r_max(), 5e-2);
  EXPECT_EQ(size_levels(std::vector<double>{}).count(), 0u);
}

TEST(SizeLevels, RatiosBeyondTheLastLevelShareIt) {
  const SizeLevels s = size_levels(std::vector<double>{1.0, 1e6});
  ASSERT_EQ(s.count(), static_cast<std::size_t>(SizeLevels::kMaxLevels));
  EXPECT_EQ(s.level[1], SizeLevels::kMaxLevels - 1);
  EXPECT_EQ(s.r_max.back(), 1e6);
}

}  // namespace
}  // namespace mpdem
