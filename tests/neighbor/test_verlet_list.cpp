// The Verlet half list (physics.md section 11) against an O(N^2) brute force applying the documented
// criterion literally (exact set comparison: the same strict inequality on both sides).
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <algorithm>
#include <cstdint>
#include <random>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include "neighbor/cell_grid.hpp"
#include "neighbor/verlet_list.hpp"
#include "support/particle_clouds.hpp"

namespace mpdem {
namespace {

using namespace test;  // Cloud, clustered, spread, jiggle, kR0

using PairSet = std::set<std::pair<std::uint32_t, std::uint32_t>>;

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

// The test clouds with radii squeezed into [kR0, 1.9 kR0]: one size level, one grid.
Cloud narrow(Cloud c) {
  for (double& r : c.r) r = kR0 + 0.9 * (r - kR0) / 4.0;
  return c;
}

// Radius ratio 1:20: 1 % of the spheres large (bimodal), or radii uniform in [kR0, 20 kR0].
Cloud wide(std::size_t n, bool bimodal, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 0.12), ur(kR0, 20 * kR0);
  Cloud c;
  for (std::size_t i = 0; i < n; ++i) {
    c.x.push_back({u(rng), u(rng), u(rng)});
    c.r.push_back(bimodal ? (i % 100 == 37 ? 20 * kR0 : kR0) : ur(rng));
  }
  return c;
}

TEST(VerletList, MatchesBruteForceForSeveralSkinsAndExtraRange) {
  int fast_paths = 0, dense_index = 0, builds = 0;
  std::vector<Cloud> clouds = test_clouds();                         // radii 1:5: size levels
  for (const Cloud& c : test_clouds()) clouds.push_back(narrow(c));  // one grid
  for (const Cloud& c : clouds) {
    for (double skin : {0.0, 0.1 * kR0, 0.5 * kR0, 2.0 * kR0}) {
      for (double extra : {0.0, 1.5 * kR0}) {
        VerletList l;
        l.build(c.x, c.r, skin, extra);
        fast_paths += l.grid_stats().morton_key;
        dense_index += l.grid_stats().dense_index;
        ++builds;
        const PairSet expect = brute_pairs(c, skin, extra);
        EXPECT_GT(expect.size(), 50u) << "test set must have pairs to be meaningful";
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

TEST(VerletList, OneGridForNarrowRadiiMatchesBruteForce) {
  for (const Cloud& wide_cloud : test_clouds()) {
    const Cloud c = narrow(wide_cloud);
    for (double skin : {0.0, 0.5 * kR0}) {
      VerletList l;
      l.build(c.x, c.r, skin, 1.5 * kR0);
      EXPECT_EQ(l.grid_stats().levels, 1u);
      const PairSet expect = brute_pairs(c, skin, 1.5 * kR0);
      EXPECT_GT(expect.size(), 100u);
      EXPECT_EQ(list_pairs(l), expect) << "skin " << skin;
    }
  }
}

TEST(VerletList, SizeLevelsMatchBruteForceForRatioOneToTwenty) {
  for (bool bimodal : {true, false}) {
    const Cloud c = wide(3000, bimodal, bimodal ? 31 : 32);
    for (double skin : {0.0, 0.2 * kR0}) {
      for (double extra : {0.0, 1.5 * kR0}) {
        VerletList l;
        l.build(c.x, c.r, skin, extra);
        EXPECT_EQ(l.grid_stats().levels, 5u);  // 1, 2, 4, 8, 16 R_min
        const PairSet expect = brute_pairs(c, skin, extra);
        EXPECT_GT(expect.size(), 1000u);
        EXPECT_EQ(list_pairs(l), expect) << (bimodal ? "bimodal" : "uniform") << " skin " << skin;
        // The large spheres' rows are long (their neighbours are found in the finer levels).
        std::size_t longest = 0;
        for (std::size_t i = 0; i < l.size(); ++i) longest = std::max(longest, l.neighbors(i).size());
        EXPECT_GT(longest, 32u);
      }
    }
  }
}

// Ghosts (periodic images or halo copies) are second members only, paired with an owned particle
// of smaller id: the same rule on one grid and on the size levels.
TEST(VerletList, GhostRuleHoldsOnOneGridAndOnSizeLevels) {
  for (bool several : {false, true}) {
    const Cloud c = several ? wide(2000, false, 41) : narrow(clustered(2000, 42));
    const std::size_t owned = 1500;
    std::vector<std::int64_t> id(c.x.size());
    for (std::size_t i = 0; i < id.size(); ++i) id[i] = static_cast<std::int64_t>((i * 7919) % 2003);
    PairSet expect;
    for (std::uint32_t i = 0; i < owned; ++i)
      for (std::uint32_t j = 0; j < c.x.size(); ++j) {
        const bool second = j < owned ? j > i : id[i] < id[j];
        const double cut = c.r[i] + c.r[j] + 0.0 + 0.3 * kR0;
        if (second && norm2(c.x[j] - c.x[i]) < cut * cut) expect.insert({i, j});
      }
    VerletList l;
    l.build(c.x, c.r, 0.3 * kR0, 0.0, owned, id);
    EXPECT_EQ(l.grid_stats().levels, several ? 5u : 1u);
    PairSet got;
    for (std::uint32_t i = 0; i < l.size(); ++i)
      for (std::uint32_t j : l.neighbors(i)) got.insert({i, j});
    EXPECT_GT(expect.size(), 500u);
    EXPECT_EQ(got, expect);
  }
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
  std::vector<Cloud> clouds = test_clouds();
  clouds.push_back(narrow(clustered(2000, 1)));
  clouds.push_back(wide(3000, true, 5));
  for (const Cloud& c : clouds) {
    std::vector<std::vector<std::uint32_t>> offs;
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

// Particles removed without a rebuild: the compacted list is the one a build at the same (build)
// positions gives for the particles left, slot for slot, and after moving them (within skin/2)
// still holds every touching pair.
TEST(VerletList, CompactedListIsTheBuildOfTheParticlesLeft) {
  const Cloud a = clustered(3000, 23);
  VerletList l;
  l.build(a.x, a.r, kR0);
  const std::size_t pairs_before = l.num_pairs();
  std::vector<char> keep(a.x.size(), 1);
  std::mt19937_64 rng(24);
  for (auto& k : keep) k = static_cast<char>(rng() % 4 != 0);
  const std::vector<std::uint32_t> from = l.compact(keep);
  Cloud left;
  std::vector<std::uint32_t> old_index;
  for (std::size_t i = 0; i < keep.size(); ++i)
    if (keep[i]) {
      left.x.push_back(a.x[i]);
      left.r.push_back(a.r[i]);
      old_index.push_back(static_cast<std::uint32_t>(i));
    }
  VerletList fresh;
  fresh.build(left.x, left.r, kR0);
  EXPECT_EQ(l.offsets(), fresh.offsets());
  EXPECT_EQ(l.indices(), fresh.indices());
  EXPECT_EQ(l.build_positions(), fresh.build_positions());
  EXPECT_EQ(l.owned(), left.x.size());
  EXPECT_LT(l.num_pairs(), pairs_before);
  // Each kept slot came from the old slot of the same pair.
  ASSERT_EQ(from.size(), l.num_pairs());
  VerletList old;
  old.build(a.x, a.r, kR0);
  for (std::size_t i = 0; i < left.x.size(); ++i)
    for (std::size_t k = l.offsets()[i]; k < l.offsets()[i + 1]; ++k) {
      const std::uint32_t was = from[k];
      ASSERT_GE(was, old.offsets()[old_index[i]]);
      ASSERT_LT(was, old.offsets()[old_index[i] + 1]);
      EXPECT_EQ(old.indices()[was], old_index[l.indices()[k]]);
    }
  const std::vector<Vec3> moved = jiggle(left.x, 0.49 * kR0, 25);
  EXPECT_FALSE(l.needs_rebuild(moved));
  const PairSet listed = list_pairs(l);
  for (const auto& pr : brute_pairs(Cloud{moved, left.r}, 0.0, 0.0))
    EXPECT_TRUE(listed.count(pr)) << pr.first << "-" << pr.second;
}

// The list's storage stays near its size across rebuilds, on one and two threads: the rows are
// written into the list itself (thread 0) and grown by reservations, not doubled. And the hook
// between listing and storing the build positions sees the pairs but no positions yet.
TEST(VerletList, StorageStaysNearItsSizeAcrossRebuilds) {
  for (const int threads : {1, 2}) {
    const int saved = omp_get_max_threads();
    omp_set_num_threads(threads);
    Cloud c = clustered(3000, 21);
    VerletList l;
    for (int build = 0; build < 3; ++build) {
      if (build > 0) l.release_build_positions();  // as NeighborSearch does before a rebuild
      std::size_t pairs_seen = 0, positions_seen = 1;
      l.build(c.x, c.r, 0.3 * kR0, 0.0, c.x.size(), {}, [&] {
        pairs_seen = l.num_pairs();
        positions_seen = l.size();
      });
      ASSERT_GT(l.num_pairs(), 3000u);
      EXPECT_EQ(pairs_seen, l.num_pairs());
      EXPECT_EQ(positions_seen, 0u);
      EXPECT_EQ(l.size(), c.x.size());
      const std::size_t n = c.x.size(), slack = 4 * 1024;  // one row's candidates
      EXPECT_LE(l.memory_bytes(), sizeof(Vec3) * n + 8 * (n + 1) + 5 * l.num_pairs() + slack)
          << threads << " threads, build " << build;
      c.x = jiggle(c.x, 0.5 * kR0, static_cast<unsigned>(build));
    }
    l.release_build_positions();
    EXPECT_EQ(l.size(), 0u);
    EXPECT_GT(l.num_pairs(), 0u);
    EXPECT_TRUE(l.needs_rebuild(c.x));
    omp_set_num_threads(saved);
  }
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

}  // namespace
}  // namespace mpdem
