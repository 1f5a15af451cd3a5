// BrickGrid: the choice of the brick counts, owners, neighbours and faces (parallel/brick_grid.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "parallel/brick_grid.hpp"

using namespace mpdem;

TEST(BrickGrid, ChoosesTheLeastCutArea) {
  const std::array<bool, 3> open{};
  // A cube: 8 ranks as 2 x 2 x 2 (cut area 3 faces), 4 as 2 x 2 x 1, 2 along x (ties go to x).
  EXPECT_EQ(BrickGrid::choose_dims(8, {1, 1, 1}, open), (std::array<int, 3>{2, 2, 2}));
  EXPECT_EQ(BrickGrid::choose_dims(4, {1, 1, 1}, open), (std::array<int, 3>{2, 2, 1}));
  EXPECT_EQ(BrickGrid::choose_dims(2, {1, 1, 1}, open), (std::array<int, 3>{2, 1, 1}));
  // A long box along z is cut across z; a prime count has one factorisation per axis.
  EXPECT_EQ(BrickGrid::choose_dims(4, {0.1, 0.1, 1.0}, open), (std::array<int, 3>{1, 1, 4}));
  EXPECT_EQ(BrickGrid::choose_dims(3, {1.0, 0.2, 0.2}, open), (std::array<int, 3>{3, 1, 1}));
  // Along a periodic axis the wrap-around face is cut too: 2 bricks cost two faces there.
  EXPECT_EQ(BrickGrid::choose_dims(2, {1.0, 1.0, 0.5}, {true, false, false}), (std::array<int, 3>{1, 2, 1}));
  EXPECT_EQ(BrickGrid::choose_dims(2, {1.0, 1.0, 0.5}, {}), (std::array<int, 3>{2, 1, 1}));
  EXPECT_EQ(BrickGrid::choose_dims(1, {1, 1, 1}, open), (std::array<int, 3>{1, 1, 1}));
}

TEST(BrickGrid, EveryPointHasOneOwnerInsideItsBrick) {
  for (const std::array<bool, 3> periodic : {std::array<bool, 3>{}, std::array<bool, 3>{true, false, true}}) {
    const BrickGrid g(12, {-1, 0, 0}, {1, 0.6, 0.9}, periodic);
    ASSERT_EQ(g.ranks(), 12);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    for (int k = 0; k < 2000; ++k) {
      const Vec3 x{u(rng), u(rng), u(rng)};
      const int r = g.owner(x);
      ASSERT_GE(r, 0);
      ASSERT_LT(r, 12);
      EXPECT_EQ(g.rank_at(g.coords(r)), r);
      for (int c = 0; c < 3; ++c) {
        double xc = x[c];
        if (periodic[static_cast<std::size_t>(c)]) {
          const double L = g.box_upper()[c] - g.box_lower()[c];
          xc -= std::floor((xc - g.box_lower()[c]) / L) * L;
        }
        EXPECT_GE(xc, g.lower(r, c));
        EXPECT_LT(xc, g.upper(r, c));
      }
    }
  }
}

TEST(BrickGrid, NeighboursAreMutualAndWrapOnlyAlongPeriodicAxes) {
  const BrickGrid g(8, {0, 0, 0}, {1, 1, 1}, {true, false, false});
  ASSERT_EQ(g.dims(), (std::array<int, 3>{2, 2, 2}));
  for (int r = 0; r < 8; ++r)
    for (int c = 0; c < 3; ++c) {
      const int up = g.neighbour(r, c, +1), down = g.neighbour(r, c, -1);
      if (up >= 0) {
        EXPECT_EQ(g.neighbour(up, c, -1), r);
      }
      if (down >= 0) {
        EXPECT_EQ(g.neighbour(down, c, +1), r);
      }
      if (c == 0) {
        EXPECT_GE(up, 0);  // periodic: always a neighbour
        EXPECT_GE(down, 0);
      } else {
        EXPECT_EQ(up < 0, g.coords(r)[static_cast<std::size_t>(c)] == 1);
        EXPECT_EQ(down < 0, g.coords(r)[static_cast<std::size_t>(c)] == 0);
        EXPECT_TRUE(std::isinf(up < 0 ? g.upper(r, c) : g.lower(r, c)));  // the outer bricks are unbounded
      }
    }
  EXPECT_DOUBLE_EQ(g.narrowest(), 0.5);
}

TEST(BrickGrid, MovedCutsChangeTheOwners) {
  BrickGrid g(2, {0, 0, 0}, {1, 0.5, 0.5}, {});
  ASSERT_EQ(g.dims(), (std::array<int, 3>{2, 1, 1}));
  EXPECT_EQ(g.owner({0.45, 0.2, 0.2}), 0);
  EXPECT_EQ(g.owner({0.55, 0.2, 0.2}), 1);
  g.set_cuts(0, {0.6});
  EXPECT_EQ(g.owner({0.55, 0.2, 0.2}), 0);
  EXPECT_DOUBLE_EQ(g.upper(0, 0), 0.6);
  EXPECT_THROW(g.set_cuts(0, {0.2, 0.4}), std::invalid_argument);
}
