// release(): frees a vector's storage, which assigning empty braces does not.
#include <gtest/gtest.h>

#include <vector>

#include "core/release.hpp"

namespace mpdem {
namespace {

TEST(Release, FreesTheStorageThatEmptyBracesKeep) {
  std::vector<double> kept(1000), freed(1000);
  kept = {};  // operator=(initializer_list): the size is 0, the capacity stays
  release(freed);
  EXPECT_TRUE(kept.empty());
  EXPECT_GE(kept.capacity(), 1000u) << "if this changes, `= {}` would do; release() stays correct";
  EXPECT_TRUE(freed.empty());
  EXPECT_EQ(freed.capacity(), 0u);
}

}  // namespace
}  // namespace mpdem
