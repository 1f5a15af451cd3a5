// The sparse cell grid (physics.md section 11): every particle in its cell, cells in Morton order; and
// the spatial reordering along that order, which must keep the Verlet list's pair set unchanged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "neighbor/cell_grid.hpp"
#include "neighbor/spatial_order.hpp"
#include "neighbor/verlet_list.hpp"
#include "state/particles.hpp"
#include "support/particle_clouds.hpp"

namespace mpdem {
namespace {

using namespace test;  // Cloud, spread, kR0

TEST(CellGrid, EveryParticleIsInItsCellAndCellsAreMortonOrdered) {
  const Cloud c = spread(2000, 0.15, 7);
  CellGrid g;
  g.build(c.x, 0.012);
  ASSERT_EQ(g.num_particles(), c.x.size());
  std::vector<int> seen(c.x.size(), 0);
  for (std::size_t cell = 0; cell < g.num_cells(); ++cell) {
    if (cell > 0) {
      EXPECT_TRUE(morton_less(g.coord(cell - 1), g.coord(cell)));
    }
    EXPECT_EQ(g.find(g.coord(cell)), cell);
    for (std::uint32_t i : g.cell_particles(cell)) {
      ++seen[i];
      EXPECT_EQ(g.cell_of(i), cell);
      EXPECT_EQ(g.coord_of(c.x[i]), g.coord(cell));
    }
  }
  for (int s : seen) EXPECT_EQ(s, 1);
  // Cell (-1, -1, -1) lies below the origin: never occupied.
  EXPECT_EQ(g.find({-1, -1, -1}), CellGrid::kNone);
}

// After a build the grid keeps what lookups need - the particle order and cell of each particle
// (8 bytes per particle), the cells and their index - and none of the sort's scratch (cell
// coordinates and two key arrays: 56 bytes per particle), on both index kinds.
TEST(CellGrid, KeepsNoSortScratchAfterTheBuild) {
  for (const bool far : {false, true}) {  // dense index; hash table (an outlier 1e4 m away)
    Cloud c = spread(5000, 0.15, 8);
    if (!far) c.x[c.x.size() / 2] = {0.07, 0.07, 0.07};
    CellGrid g;
    g.build(c.x, 0.006);
    const std::size_t n = c.x.size(), cells = g.num_cells();
    EXPECT_EQ(g.uses_dense_index(), !far);
    const std::size_t bound = 8 * n + 2 * cells * (sizeof(CellCoord) + 4) + 4 * (g.hash_slots() + g.dense_slots()) + 64;
    EXPECT_LE(g.memory_bytes(), bound) << (far ? "hash table" : "dense index");
  }
}

TEST(CellGrid, MortonComparisonMatchesInterleavedKey) {
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<std::int64_t> u(0, (1 << 21) - 1), small(0, 7);
  for (int t = 0; t < 20000; ++t) {
    // Mix of wide and tiny coordinates so equal-msb ties are exercised.
    const bool tiny = t % 2 == 0;
    auto pick = [&] { return tiny ? small(rng) : u(rng); };
    const CellCoord a{pick(), pick(), pick()}, b{pick(), pick(), pick()};
    EXPECT_EQ(morton_less(a, b), morton_key(a) < morton_key(b)) << t;
  }
}

TEST(SpatialOrder, IsAPermutationAndPreservesThePairSet) {
  const Cloud c = spread(2000, 0.15, 17);
  Particles p;
  for (std::size_t i = 0; i < c.x.size(); ++i)
    p.add(static_cast<std::int64_t>(1000 + 3 * i), 0, c.r[i], 2500.0, c.x[i], {});
  const double skin = 0.5 * kR0;
  VerletList before;
  before.build(p.x, p.radius, skin);
  std::set<std::pair<std::int64_t, std::int64_t>> ids_before, ids_after;
  for (std::uint32_t i = 0; i < p.size(); ++i)
    for (std::uint32_t j : before.neighbors(i)) ids_before.insert(std::minmax(p.id[i], p.id[j]));

  const std::vector<std::uint32_t> order = spatial_order(p.x, 2 * 5 * kR0 + skin);
  ASSERT_EQ(order.size(), p.size());
  std::vector<std::uint32_t> check = order;
  std::sort(check.begin(), check.end());
  for (std::uint32_t k = 0; k < check.size(); ++k) ASSERT_EQ(check[k], k);

  // Locality: consecutive particles are far closer after ordering. For uniform random points
  // the mean consecutive distance is ~0.66 box before and ~ (box^3/N)^(1/3) ~ 0.1 box after
  // along a space-filling curve; require a factor 3 improvement.
  auto path = [](const std::vector<Vec3>& x) {
    double s = 0.0;
    for (std::size_t k = 1; k < x.size(); ++k) s += std::min(norm(x[k] - x[k - 1]), 1.0);  // cap the outlier hop
    return s;
  };
  const double path_before = path(p.x);
  p.permute(order);
  EXPECT_LT(path(p.x), path_before / 3.0);

  VerletList after;
  after.build(p.x, p.radius, skin);
  for (std::uint32_t i = 0; i < p.size(); ++i)
    for (std::uint32_t j : after.neighbors(i)) ids_after.insert(std::minmax(p.id[i], p.id[j]));
  EXPECT_GT(ids_before.size(), 100u);
  EXPECT_EQ(ids_after, ids_before);
}

}  // namespace
}  // namespace mpdem
