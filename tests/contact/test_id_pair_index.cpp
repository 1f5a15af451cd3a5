// IdPairIndex: every stored pair is found at its record, absent pairs (the reversed order too)
// are not, and of two records of one pair the first is found.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "contact/id_pair_index.hpp"

namespace mpdem {
namespace {

using Pair = std::pair<std::int64_t, std::int64_t>;

TEST(IdPairIndex, FindsEveryStoredPairAndNoOther) {
  std::mt19937_64 rng(7);
  // Ids as a run's are: mostly small and dense, some far apart (an inlet's later ids).
  std::uniform_int_distribution<std::int64_t> dense(0, 3000), far(0, std::int64_t{1} << 40);
  std::set<Pair> stored;
  std::vector<Pair> keys;
  while (keys.size() < 20000) {
    std::int64_t a = keys.size() % 5 == 0 ? far(rng) : dense(rng), b = dense(rng);
    if (a == b) continue;
    if (a > b) std::swap(a, b);
    if (stored.insert({a, b}).second) keys.push_back({a, b});
  }
  const auto key = [&keys](std::size_t r) { return keys[r]; };
  IdPairIndex index;
  index.build(keys.size(), key);
  for (std::size_t r = 0; r < keys.size(); ++r) ASSERT_EQ(index.find(keys[r].first, keys[r].second, key), r);
  std::size_t absent = 0;
  for (int t = 0; t < 20000; ++t) {
    std::int64_t a = dense(rng), b = dense(rng);
    if (a > b) std::swap(a, b);
    if (a == b || stored.count({a, b}) > 0) continue;
    ++absent;
    EXPECT_EQ(index.find(a, b, key), IdPairIndex::npos) << a << " " << b;
  }
  EXPECT_GT(absent, 10000u);
  // Stored as (lower, higher): the reversed order is another key.
  std::size_t reversed = 0;
  for (const Pair& k : keys)
    if (stored.count({k.second, k.first}) == 0) {
      ++reversed;
      EXPECT_EQ(index.find(k.second, k.first, key), IdPairIndex::npos);
    }
  EXPECT_EQ(reversed, keys.size());
}

TEST(IdPairIndex, TheFirstOfTwoRecordsOfAPairIsFound) {
  const std::vector<Pair> keys{{1, 2}, {3, 4}, {1, 2}, {5, 6}, {3, 4}};
  const auto key = [&keys](std::size_t r) { return keys[r]; };
  IdPairIndex index;
  index.build(keys.size(), key);
  EXPECT_EQ(index.find(1, 2, key), 0u);
  EXPECT_EQ(index.find(3, 4, key), 1u);
  EXPECT_EQ(index.find(5, 6, key), 3u);
}

TEST(IdPairIndex, EmptyFindsNothing) {
  const auto key = [](std::size_t) { return Pair{0, 0}; };
  IdPairIndex unbuilt, empty;
  empty.build(0, key);
  EXPECT_EQ(unbuilt.find(0, 1, key), IdPairIndex::npos);
  EXPECT_EQ(empty.find(0, 1, key), IdPairIndex::npos);
}

}  // namespace
}  // namespace mpdem
