// Communicator on 1 to N ranks (run by ctest under mpirun -np 1, 2, 3, 4; parallel/communicator.hpp):
// the fixed-size gather puts every rank's bytes in rank order, the reductions combine the ranks
// in rank order (the same bits as a loop over the ranks' values, on every rank), the best of the
// ranks goes to the lowest rank on a tie, and an exchange of known length carries the bytes of
// any length, none included.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "parallel/communicator.hpp"
#include "parallel/gather.hpp"

using namespace mpdem;

namespace {
// Rank r's values: magnitudes far apart, so that another order of the sum gives other bits.
double value(int r, std::size_t k) {
  return (r % 2 == 0 ? 1.0 : -1.0) * std::ldexp(1.0 + 0.1 * static_cast<double>(k), 40 * (r % 3)) + 0.3 * r;
}
}  // namespace

TEST(Communicator, FixedGatherIsInRankOrder) {
  const Communicator& comm = Communicator::world();
  const std::int64_t mine[2] = {comm.rank(), 100 + comm.rank()};
  const std::vector<std::byte> all = comm.all_gather_fixed(std::as_bytes(std::span(mine)));
  ASSERT_EQ(all.size(), sizeof mine * static_cast<std::size_t>(comm.size()));
  for (int r = 0; r < comm.size(); ++r) {
    std::int64_t got[2];
    std::memcpy(got, all.data() + static_cast<std::size_t>(r) * sizeof got, sizeof got);
    EXPECT_EQ(got[0], r);
    EXPECT_EQ(got[1], 100 + r);
  }
}

// Ranks holding r values each (rank 0 none): every rank gets all of them, concatenated in rank
// order; gather_values only on the root.
TEST(Communicator, GatheredValuesAreConcatenatedInRankOrder) {
  const Communicator& comm = Communicator::world();
  std::vector<std::int64_t> mine;
  for (int k = 0; k < comm.rank(); ++k) mine.push_back(1000 * comm.rank() + k);
  const std::vector<std::int64_t> every = all_gather_values<std::int64_t>(comm, mine);
  const std::vector<std::int64_t> at_root = gather_values<std::int64_t>(comm, mine, 0);
  std::vector<std::int64_t> expected;
  for (int r = 0; r < comm.size(); ++r)
    for (int k = 0; k < r; ++k) expected.push_back(1000 * r + k);
  EXPECT_EQ(every, expected);
  EXPECT_EQ(at_root, comm.rank() == 0 ? expected : std::vector<std::int64_t>{});
}

TEST(Communicator, SumsAndMaximaInRankOrder) {
  const Communicator& comm = Communicator::world();
  std::vector<double> sum(3), max(3);
  for (std::size_t k = 0; k < sum.size(); ++k) sum[k] = max[k] = value(comm.rank(), k);
  comm.sum(sum);
  comm.max(max);
  for (std::size_t k = 0; k < sum.size(); ++k) {
    double s = value(0, k), m = value(0, k);
    for (int r = 1; r < comm.size(); ++r) {
      s += value(r, k);
      m = std::max(m, value(r, k));
    }
    EXPECT_EQ(sum[k], s) << "k = " << k;
    EXPECT_EQ(max[k], m) << "k = " << k;
  }
  const std::uint64_t n = comm.sum(std::uint64_t{3} + static_cast<std::uint64_t>(comm.rank()));
  EXPECT_EQ(n, static_cast<std::uint64_t>(3 * comm.size() + comm.size() * (comm.size() - 1) / 2));
  EXPECT_EQ(comm.any(comm.rank() == comm.size() - 1), true);
  EXPECT_EQ(comm.any(false), false);
}

TEST(Communicator, BestAcrossTakesTheLowestRankOnATie) {
  const Communicator& comm = Communicator::world();
  // Ranks 1 and up tie at 7: the best is rank 1's (or rank 0's 5 on one rank).
  const auto [best, rank] = best_across(comm, comm.rank() == 0 ? 5 : 7, [](int a, int b) { return a > b; });
  EXPECT_EQ(best, comm.size() == 1 ? 5 : 7);
  EXPECT_EQ(rank, comm.size() == 1 ? 0 : 1);
}

TEST(Communicator, KnownLengthExchangeAroundARing) {
  const Communicator& comm = Communicator::world();
  const int n = comm.size(), me = comm.rank();
  // Rank r sends r + 1 bytes (rank n-1: none at all) to the next rank, so the length received is
  // known: the previous rank's.
  const int to = (me + 1) % n, from = (me + n - 1) % n;
  const std::vector<std::byte> out(static_cast<std::size_t>(me == n - 1 ? 0 : me + 1), std::byte{0x5a});
  const std::size_t n_in = from == n - 1 ? 0 : static_cast<std::size_t>(from + 1);
  const std::vector<std::byte> in = comm.exchange_known(to, out, from, n_in, 40);
  EXPECT_EQ(in, std::vector<std::byte>(n_in, std::byte{0x5a}));
  // To no rank and from none.
  EXPECT_TRUE(comm.exchange_known(-1, out, -1, 0, 50).empty());
  if (n == 1) {
    EXPECT_THROW(comm.exchange_known(0, out, 0, out.size() + 1, 60), std::runtime_error);
  }
}
