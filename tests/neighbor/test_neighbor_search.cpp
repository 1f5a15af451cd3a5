// Neighbour search (physics.md section 11): the sparse cell grid, the Verlet half list, the
// spatial reordering and the barrier broad phase, each checked against an O(N^2) / O(N M) brute
// force that applies the documented criterion literally. Set comparisons are exact (the
// criterion is a strict inequality evaluated with the same expression on both sides).
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "neighbor/barrier_broadphase.hpp"
#include "neighbor/cell_grid.hpp"
#include "neighbor/spatial_order.hpp"
#include "neighbor/verlet_list.hpp"
#include "state/barriers.hpp"
#include "state/particles.hpp"

namespace mpdem {
namespace {

using PairSet = std::set<std::pair<std::uint32_t, std::uint32_t>>;

constexpr double kR0 = 1e-3;  // m, smallest radius of the test sets

struct Cloud {
  std::vector<Vec3> x;    // m
  std::vector<double> r;  // m
};

// Radii uniform in [kR0, 5 kR0] (ratio 1:5).
double random_radius(std::mt19937_64& rng) { return std::uniform_real_distribution<double>(kR0, 5 * kR0)(rng); }

// N particles in a few tight Gaussian clusters (dense: many pairs per particle).
Cloud clustered(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 0.01);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  std::vector<Vec3> centres(5);
  for (auto& c : centres) c = {u(rng), u(rng), u(rng)};
  Cloud c;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& k = centres[i % centres.size()];
    c.x.push_back({k.x + g(rng), k.y + g(rng), k.z + g(rng)});
    c.r.push_back(random_radius(rng));
  }
  return c;
}

// N-1 particles uniform in a box of side `box` and one outlier `outlier` m away along x.
Cloud spread(std::size_t n, double box, unsigned seed, double outlier = 1e4) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, box);
  Cloud c;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    c.x.push_back({u(rng), u(rng), u(rng)});
    c.r.push_back(random_radius(rng));
  }
  c.x.insert(c.x.begin() + static_cast<std::ptrdiff_t>(n / 2), Vec3{outlier, -3.0, 2.0});
  c.r.insert(c.r.begin() + static_cast<std::ptrdiff_t>(n / 2), 5 * kR0);
  return c;
}

// The documented criterion, applied to all pairs.
PairSet brute_pairs(const Cloud& c, double skin, double extra) {
  PairSet s;
  for (std::uint32_t i = 0; i < c.x.size(); ++i)
    for (std::uint32_t j = i + 1; j < c.x.size(); ++j) {
      const double cut = c.r[i] + c.r[j] + extra + skin;
      if (norm2(c.x[j] - c.x[i]) < cut * cut) s.insert({i, j});
    }
  return s;
}

// Pairs of a list; also checks the CSR shape: j > i, strictly ascending per i.
PairSet list_pairs(const VerletList& l) {
  PairSet s;
  EXPECT_EQ(l.offsets().size(), l.size() + 1);
  EXPECT_EQ(l.offsets().back(), l.indices().size());
  for (std::uint32_t i = 0; i < l.size(); ++i) {
    const auto nb = l.neighbors(i);
    for (std::size_t k = 0; k < nb.size(); ++k) {
      EXPECT_GT(nb[k], i);
      if (k > 0) {
        EXPECT_LT(nb[k - 1], nb[k]);
      }
      s.insert({i, nb[k]});
    }
  }
  return s;
}

// Dense clusters; a uniform box with an outlier 1e4 m away (fewer than 2^21 cells per axis:
// Morton-key sort); a denser box with an outlier 1e5 m away (more than 2^21 cells per axis:
// bitwise Z-order comparison sort). Both sort paths are thus compared with brute force.
std::vector<Cloud> test_clouds() {
  return {clustered(2000, 1), spread(2000, 0.15, 2, 1e4), spread(2000, 0.08, 3, 1e5)};
}

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

TEST(VerletList, MatchesBruteForceForSeveralSkinsAndExtraRange) {
  int fast_paths = 0, dense_index = 0, builds = 0;
  for (const Cloud& c : test_clouds()) {
    for (double skin : {0.0, 0.1 * kR0, 0.5 * kR0, 2.0 * kR0}) {
      for (double extra : {0.0, 1.5 * kR0}) {
        VerletList l;
        l.build(c.x, c.r, skin, extra);
        fast_paths += l.grid_stats().morton_key;
        dense_index += l.grid_stats().dense_index;
        ++builds;
        const PairSet expect = brute_pairs(c, skin, extra);
        EXPECT_GT(expect.size(), 100u) << "test set must have pairs to be meaningful";
        EXPECT_EQ(list_pairs(l), expect) << "skin " << skin << " extra " << extra;
        EXPECT_EQ(l.num_pairs(), expect.size());
      }
    }
  }
  // Both sort paths and both cell indexes (dense box array, hash table) were exercised.
  EXPECT_GT(fast_paths, 0);
  EXPECT_LT(fast_paths, builds);
  EXPECT_GT(dense_index, 0);
  EXPECT_LT(dense_index, builds);
}

// Moves every particle by a random vector of length < max_step.
std::vector<Vec3> jiggle(const std::vector<Vec3>& x, double max_step, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> y = x;
  for (auto& p : y) {
    Vec3 d{g(rng), g(rng), g(rng)};
    d = d * (max_step * u(rng) / norm(d));
    p += d;
  }
  return y;
}

TEST(VerletList, KeepsEveryTruePairWhileMotionBelowHalfSkin) {
  const double skin = 1.0 * kR0;
  for (const Cloud& c : test_clouds()) {
    for (double extra : {0.0, 1.5 * kR0}) {
      VerletList l;
      l.build(c.x, c.r, skin, extra);
      const PairSet listed = list_pairs(l);
      Cloud moved{jiggle(c.x, 0.499 * skin, 5), c.r};
      ASSERT_FALSE(l.needs_rebuild(moved.x));
      const PairSet now = brute_pairs(moved, 0.0, extra);  // pairs truly within range now
      const PairSet before = brute_pairs(c, 0.0, extra);
      std::size_t fresh = 0;  // pairs that came into range during the motion
      for (const auto& p : now) {
        EXPECT_TRUE(listed.count(p)) << p.first << "-" << p.second;
        fresh += before.count(p) == 0;
      }
      EXPECT_GT(fresh, 0u) << "motion should bring new pairs into range for the test to bite";
    }
  }
}

TEST(VerletList, NeedsRebuildFlipsExactlyAtHalfSkin) {
  const Cloud c = clustered(2000, 9);
  const double skin = 0.8 * kR0;
  VerletList l;
  l.build(c.x, c.r, skin);
  EXPECT_FALSE(l.needs_rebuild(c.x));
  EXPECT_EQ(l.max_displacement(c.x), 0.0);
  for (double f : {0.5 * (1 - 1e-9), 0.5 * (1 + 1e-9)}) {
    std::vector<Vec3> y = c.x;
    y[1234].y += f * skin;
    EXPECT_EQ(l.needs_rebuild(y), f > 0.5) << f;
    // Displacement reported to rounding of the 0.1 m coordinates (1e-12 relative is ample).
    EXPECT_NEAR(l.max_displacement(y), f * skin, 1e-12 * skin);
  }
  std::vector<Vec3> fewer(c.x.begin(), c.x.end() - 1);
  EXPECT_TRUE(l.needs_rebuild(fewer));
  VerletList never_built;
  EXPECT_TRUE(never_built.needs_rebuild(c.x));
}

TEST(VerletList, IdenticalForOneTwoAndFourThreads) {
  const int saved = omp_get_max_threads();
  for (const Cloud& c : test_clouds()) {
    std::vector<std::vector<std::size_t>> offs;
    std::vector<std::vector<std::uint32_t>> idx;
    for (int nt : {1, 2, 4}) {
      omp_set_num_threads(nt);
      VerletList l;
      l.build(c.x, c.r, 0.5 * kR0, 1.0 * kR0);
      offs.push_back(l.offsets());
      idx.push_back(l.indices());
    }
    EXPECT_EQ(offs[0], offs[1]);
    EXPECT_EQ(idx[0], idx[1]);
    EXPECT_EQ(offs[0], offs[2]);
    EXPECT_EQ(idx[0], idx[2]);
  }
  omp_set_num_threads(saved);
}

TEST(VerletList, RebuildingReusesStateCorrectly) {
  // A list rebuilt on a different set must describe only the new set.
  VerletList l;
  const Cloud a = clustered(2000, 21), b = spread(500, 0.05, 22);
  l.build(a.x, a.r, kR0);
  l.build(b.x, b.r, kR0);
  EXPECT_EQ(list_pairs(l), brute_pairs(b, kR0, 0.0));
}

TEST(VerletList, RejectsInvalidInput) {
  Cloud c = clustered(50, 3);
  VerletList l;
  EXPECT_THROW(l.build(c.x, c.r, -1.0), std::invalid_argument);
  EXPECT_THROW(l.build(c.x, std::vector<double>(49, kR0), 0.0), std::invalid_argument);
  c.x[7].x = std::nan("");
  EXPECT_THROW(l.build(c.x, c.r, 0.0), std::invalid_argument);
  VerletList empty;
  empty.build({}, {}, kR0);
  EXPECT_EQ(empty.num_pairs(), 0u);
  EXPECT_EQ(empty.offsets().size(), 1u);
}

TEST(VerletList, MemoryIsLinearInParticlesForAHugeBox) {
  // 1000 particles over a 1e6 m box: a dense grid of 2-10 mm cells would need ~1e26 cells.
  const std::size_t n = 1000;
  const Cloud c = spread(n, 1e6, 13);
  VerletList l;
  l.build(c.x, c.r, kR0);
  EXPECT_EQ(l.num_pairs(), 0u);  // no two particles are near each other in such a box
  const VerletList::GridStats& g = l.grid_stats();
  EXPECT_LE(g.cells, n);
  EXPECT_LE(g.hash_slots, 4 * n);
  EXPECT_LE(static_cast<double>(g.dense_slots), CellGrid::kDenseFactor * static_cast<double>(n));
  // Bound from the container layout (~200 bytes per particle, see cell_grid.hpp), doubled for
  // growth slack: 512 bytes per particle for the grid while building; between builds the list
  // keeps its centres at build time, offsets and pairs only (here no pairs: 32 bytes).
  EXPECT_LE(g.bytes, 512 * n);
  EXPECT_GT(g.bytes, 0u);
  EXPECT_LE(l.memory_bytes(), 64 * n);
  EXPECT_EQ(brute_pairs(c, kR0, 0.0).size(), 0u);
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
    for (std::uint32_t j : before.neighbors(i))
      ids_before.insert(std::minmax(p.id[i], p.id[j]));

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
    for (std::uint32_t j : after.neighbors(i))
      ids_after.insert(std::minmax(p.id[i], p.id[j]));
  EXPECT_GT(ids_before.size(), 100u);
  EXPECT_EQ(ids_after, ids_before);
}

// ---------------------------------------------------------------- barrier broad phase

// A 10 x 10 grid of small triangles around the clusters, a tilted mid-size one, and one huge
// triangle of side 100 m in the plane z = -0.2 whose centroid is ~30 m from the particles.
Barriers test_barriers() {
  Barriers b;
  std::int64_t id = 0;
  const double h = 0.03;
  for (int a = 0; a < 10; ++a)
    for (int c = 0; c < 10; ++c) {
      const Vec3 o{-0.15 + h * a, -0.15 + h * c, -0.02};
      b.add(id++, o, o + Vec3{h, 0, 0}, o + Vec3{0, h, 0.01}, 0, 1e9, 0.3, {}, 0.002 * (a % 3), 300.0);
    }
  b.add(id++, {0.0, 0.0, 0.0}, {0.05, 0.02, 0.04}, {-0.01, 0.06, 0.02}, 0, 1e9, 0.3, {}, 0.0, 300.0);
  b.add(id++, {-1.0, -1.0, -0.2}, {99.0, -1.0, -0.2}, {-1.0, 99.0, -0.2}, 0, 1e9, 0.3, {}, 0.001, 300.0);
  return b;
}

// Particles: one cluster set plus 500 particles just above the huge triangle, near its corner.
Cloud barrier_cloud() {
  Cloud c = clustered(1500, 31);
  std::mt19937_64 rng(32);
  std::uniform_real_distribution<double> u(-0.9, 0.5), z(-0.21, -0.185);
  for (int k = 0; k < 500; ++k) {
    c.x.push_back({u(rng), u(rng), z(rng)});
    c.r.push_back(random_radius(rng));
  }
  return c;
}

std::vector<std::vector<std::uint32_t>> brute_candidates(const Cloud& c, const Barriers& b, double skin) {
  std::vector<std::vector<std::uint32_t>> out(c.x.size());
  for (std::size_t i = 0; i < c.x.size(); ++i)
    for (std::uint32_t e = 0; e < b.size(); ++e) {
      Vec3 lo = b.vertex(e, 0), hi = lo;
      for (int k = 1; k < 3; ++k) {
        const Vec3 v = b.vertex(e, k);
        lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
        hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
      }
      const double m = c.r[i] + (0.5 * b.thickness[e] + skin);
      const Vec3& p = c.x[i];
      if (p.x >= lo.x - m && p.x <= hi.x + m && p.y >= lo.y - m && p.y <= hi.y + m && p.z >= lo.z - m &&
          p.z <= hi.z + m)
        out[i].push_back(e);
    }
  return out;
}

std::vector<std::vector<std::uint32_t>> candidate_lists(const BarrierBroadphase& bp) {
  std::vector<std::vector<std::uint32_t>> out(bp.size());
  for (std::size_t i = 0; i < bp.size(); ++i) {
    const auto s = bp.candidates(i);
    out[i].assign(s.begin(), s.end());
  }
  return out;
}

TEST(BarrierBroadphase, MatchesBruteForceIncludingAHugeTriangle) {
  const Cloud c = barrier_cloud();
  Barriers b = test_barriers();
  b.offset[3] = {0.001, -0.002, 0.0005};  // a moved element: current vertices must be used
  const std::uint32_t huge = static_cast<std::uint32_t>(b.size() - 1);
  for (double skin : {0.0, 0.5 * kR0, 3.0 * kR0}) {
    BarrierBroadphase bp;
    bp.build(c.x, c.r, b, skin);
    const auto expect = brute_candidates(c, b, skin);
    EXPECT_EQ(candidate_lists(bp), expect) << "skin " << skin;
    std::size_t far_hits = 0, total = 0;
    for (std::size_t i = 0; i < expect.size(); ++i) {
      total += expect[i].size();
      far_hits += std::count(expect[i].begin(), expect[i].end(), huge);
    }
    EXPECT_EQ(bp.num_candidates(), total);
    EXPECT_GT(far_hits, 100u) << "particles ~30 m from the huge triangle's centroid must see it";
    EXPECT_GT(total - far_hits, 100u) << "small elements must have candidates too";
  }
}

TEST(BarrierBroadphase, IdenticalForOneTwoAndFourThreads) {
  const int saved = omp_get_max_threads();
  const Cloud c = barrier_cloud();
  const Barriers b = test_barriers();
  std::vector<std::vector<std::uint32_t>> idx;
  std::vector<std::vector<std::size_t>> offs;
  for (int nt : {1, 2, 4}) {
    omp_set_num_threads(nt);
    BarrierBroadphase bp;
    bp.build(c.x, c.r, b, kR0);
    idx.push_back(bp.indices());
    offs.push_back(bp.offsets());
  }
  omp_set_num_threads(saved);
  EXPECT_EQ(idx[0], idx[1]);
  EXPECT_EQ(offs[0], offs[1]);
  EXPECT_EQ(idx[0], idx[2]);
  EXPECT_EQ(offs[0], offs[2]);
}

TEST(BarrierBroadphase, KeepsEveryTrueCandidateWhileCombinedMotionBelowHalfSkin) {
  const double skin = 2.0 * kR0;
  const Cloud c = barrier_cloud();
  Barriers b = test_barriers();
  BarrierBroadphase bp;
  bp.build(c.x, c.r, b, skin);
  VerletList l;
  l.build(c.x, c.r, skin);
  // Particles move up to 0.3 skin, barriers 0.19 skin: combined 0.49 skin < skin/2.
  Cloud moved{jiggle(c.x, 0.3 * skin, 41), c.r};
  for (std::size_t e = 0; e < b.size(); ++e) b.offset[e] += Vec3{0.0, 0.0, (e % 2 ? 0.19 : -0.19) * skin};
  const double dp = l.max_displacement(moved.x);
  ASSERT_LT(dp, 0.3 * skin);
  EXPECT_NEAR(bp.max_barrier_displacement(b), 0.19 * skin, 1e-12);
  ASSERT_FALSE(bp.needs_rebuild(b, dp));
  const auto now = brute_candidates(moved, b, 0.0);  // boxes a true contact must lie in
  std::size_t checked = 0;
  for (std::size_t i = 0; i < now.size(); ++i) {
    const auto have = bp.candidates(i);
    for (std::uint32_t e : now[i]) {
      EXPECT_TRUE(std::binary_search(have.begin(), have.end(), e)) << i << " " << e;
      ++checked;
    }
  }
  EXPECT_GT(checked, 200u);
  // Rebuild rule: dp + db > skin/2 exactly.
  EXPECT_FALSE(bp.needs_rebuild(b, 0.5 * skin - 0.19 * skin - 1e-9 * skin));
  EXPECT_TRUE(bp.needs_rebuild(b, 0.5 * skin - 0.19 * skin + 1e-9 * skin));
  b.add(999, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0, 1e9, 0.3, {}, 0.0, 300.0);
  EXPECT_TRUE(bp.needs_rebuild(b, 0.0));  // element count changed
}

TEST(BarrierBroadphase, NoBarriersAndNoParticles) {
  const Cloud c = clustered(100, 5);
  BarrierBroadphase bp;
  bp.build(c.x, c.r, Barriers{}, kR0);
  EXPECT_EQ(bp.size(), c.x.size());
  EXPECT_EQ(bp.num_candidates(), 0u);
  bp.build({}, {}, test_barriers(), kR0);
  EXPECT_EQ(bp.size(), 0u);
  EXPECT_EQ(bp.num_candidates(), 0u);
}

}  // namespace
}  // namespace mpdem
