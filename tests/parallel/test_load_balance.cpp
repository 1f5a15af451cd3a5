// The cut planes' shift (parallel/load_balance.hpp) on one process: the cost histogram of one
// rank is the summed histogram of a run, so the quantile placement and its limits are checked
// without MPI (the collective side: tests/parallel/mpi_load_balance.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "parallel/load_balance.hpp"

using namespace mpdem;

namespace {

// n points uniform in [a, b] along x (y, z in the unit square).
std::vector<Vec3> points(std::size_t n, double a, double b, std::uint64_t seed) {
  std::vector<Vec3> x(n);
  std::uint64_t s = seed;
  auto u = [&] {  // splitmix64 to [0, 1)
    s += 0x9E3779B97F4A7C15ull;
    std::uint64_t z = s;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
  };
  for (Vec3& p : x) p = {a + (b - a) * u(), u(), u()};
  return x;
}

// 4 bricks along x over [0, 1] x [0, 0.1] x [0, 0.1].
BrickGrid four_along_x(bool periodic) { return BrickGrid(4, {0, 0, 0}, {1, 0.1, 0.1}, {periodic, false, false}); }

}  // namespace

TEST(LoadBalance, ImbalanceIsMaxOverMean) {
  const Communicator& one = Communicator::single();
  EXPECT_DOUBLE_EQ(imbalance(one, 3.0), 1.0);  // one rank is always balanced
  EXPECT_DOUBLE_EQ(imbalance(one, 0.0), 1.0);
}

TEST(LoadBalance, CutsConvergeToTheQuantilesMovingOneBrickAtATime) {
  const Communicator& one = Communicator::single();
  BrickGrid g = four_along_x(false);
  ASSERT_EQ(g.dims()[0], 4);
  // Every particle in the lower half: the balanced cuts are at 1/8, 2/8, 3/8.
  const std::vector<Vec3> x = points(40000, 0.0, 0.5, 7);
  const double want[] = {0.125, 0.25, 0.375};
  for (int round = 0; round < 6; ++round) {
    const BrickGrid before = g;
    const bool moved = shift_cuts(g, one, x, 1.0, 0.05);
    if (round == 0) {
      EXPECT_TRUE(moved);
    }
    // A particle changes owner by at most one brick (what one migration can carry).
    for (const Vec3& p : x) EXPECT_LE(std::abs(g.brick_along(0, p.x) - before.brick_along(0, p.x)), 1);
    for (std::size_t k = 1; k < g.cuts(0).size(); ++k) EXPECT_GE(g.cuts(0)[k] - g.cuts(0)[k - 1], 0.05 - 1e-12);
  }
  // Within a histogram bin (1/64 of a brick) and the sampling noise of 40000 points.
  for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(g.cuts(0)[k], want[k], 0.01) << "cut " << k;
  shift_cuts(g, one, x, 1.0, 0.05);  // balanced: a further shift stays there
  for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(g.cuts(0)[k], want[k], 0.01) << "cut " << k;
  // The other axes are not cut.
  EXPECT_TRUE(g.cuts(1).empty());
  EXPECT_TRUE(g.cuts(2).empty());
}

TEST(LoadBalance, BricksStayWiderThanTheHalo) {
  const Communicator& one = Communicator::single();
  BrickGrid g = four_along_x(false);
  // Everything within [0, 0.1]: balanced cuts would be 0.025 apart; the halo needs 0.2.
  const std::vector<Vec3> x = points(20000, 0.0, 0.1, 11);
  for (int round = 0; round < 6; ++round) shift_cuts(g, one, x, 1.0, 0.2);
  for (std::size_t k = 1; k < g.cuts(0).size(); ++k) EXPECT_GE(g.cuts(0)[k] - g.cuts(0)[k - 1], 0.2 - 1e-12);
  EXPECT_LT(g.cuts(0)[0], 0.25);  // it moved towards the load as far as the widths allow
}

TEST(LoadBalance, PeriodicAxisKeepsItsEndBricksWide) {
  const Communicator& one = Communicator::single();
  BrickGrid g = four_along_x(true);
  const std::vector<Vec3> x = points(20000, 0.6, 1.0, 5);
  for (int round = 0; round < 8; ++round) shift_cuts(g, one, x, 1.0, 0.08);
  const std::vector<double>& c = g.cuts(0);
  EXPECT_GE(c.front() - 0.0, 0.08 - 1e-12);  // the first brick [0, c0)
  EXPECT_GE(1.0 - c.back(), 0.08 - 1e-12);   // the last [c2, 1), its neighbour across the face
  for (std::size_t k = 1; k < c.size(); ++k) EXPECT_GE(c[k] - c[k - 1], 0.08 - 1e-12);
  // The load is in [0.6, 1]: the cuts gathered there (the first brick holds [0, c0) mostly empty).
  EXPECT_GT(c.front(), 0.5);
}

TEST(LoadBalance, NoCostNoMove) {
  const Communicator& one = Communicator::single();
  BrickGrid g = four_along_x(false);
  const std::vector<double> old = g.cuts(0);
  EXPECT_FALSE(shift_cuts(g, one, {}, 0.0, 0.05));
  EXPECT_EQ(g.cuts(0), old);
}
