// The barrier broad phase (physics.md section 11) against an O(N M) brute force of the documented
// distance criterion, including a huge triangle far from its centroid; threads; the combined-motion
// rebuild rule; a slanted element whose box holds particles far from it.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "neighbor/barrier_broadphase.hpp"
#include "neighbor/verlet_list.hpp"
#include "geometry/triangle_closest_point.hpp"
#include "state/barriers.hpp"
#include "support/particle_clouds.hpp"

namespace mpdem {
namespace {

using namespace test;  // Cloud, clustered, random_radius, jiggle, kR0

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

// Elements within distance margin * (1 + rel) of each centre, margin = R + t_b/2 + skin: with
// rel = -1e-6 those the broad phase must list, with rel = +1e-6 all it may list (the header's
// rounding allowance lies between).
std::vector<std::vector<std::uint32_t>> brute_candidates(const Cloud& c, const Barriers& b, double skin,
                                                         double rel = 0.0) {
  std::vector<std::vector<std::uint32_t>> out(c.x.size());
  for (std::size_t i = 0; i < c.x.size(); ++i)
    for (std::uint32_t e = 0; e < b.size(); ++e) {
      const double m = (c.r[i] + (0.5 * b.thickness[e] + skin)) * (1.0 + rel);
      const Vec3& p = c.x[i];
      if (norm(closest_point_on_triangle(p, b.vertex(e, 0), b.vertex(e, 1), b.vertex(e, 2)).point - p) <= m)
        out[i].push_back(e);
    }
  return out;
}

// Every list of `inner` is contained in the same particle's list of `outer`.
bool contained(const std::vector<std::vector<std::uint32_t>>& inner,
               const std::vector<std::vector<std::uint32_t>>& outer) {
  for (std::size_t i = 0; i < inner.size(); ++i)
    if (!std::includes(outer[i].begin(), outer[i].end(), inner[i].begin(), inner[i].end())) return false;
  return true;
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
    const auto got = candidate_lists(bp);
    EXPECT_TRUE(contained(brute_candidates(c, b, skin, -1e-6), got)) << "skin " << skin;
    EXPECT_TRUE(contained(got, brute_candidates(c, b, skin, 1e-6))) << "skin " << skin;
    std::size_t far_hits = 0, total = 0;
    for (std::size_t i = 0; i < expect.size(); ++i) {
      total += expect[i].size();
      far_hits += std::count(expect[i].begin(), expect[i].end(), huge);
    }
    EXPECT_EQ(bp.num_candidates(), total) << "no centre this close to a margin in this cloud";
    EXPECT_GT(far_hits, 100u) << "particles ~30 m from the huge triangle's centroid must see it";
    EXPECT_GT(total - far_hits, 100u) << "small elements must have candidates too";
  }
}

TEST(BarrierBroadphase, IdenticalForOneTwoAndFourThreads) {
  const int saved = omp_get_max_threads();
  const Cloud c = barrier_cloud();
  const Barriers b = test_barriers();
  std::vector<std::vector<std::uint32_t>> idx;
  std::vector<std::vector<std::uint32_t>> offs;
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
  const auto now = brute_candidates(moved, b, 0.0);  // the true contacts and those just short of one
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

// A long element slanted across the axes (a hopper's cone, a drum's wall): its box holds a whole
// slab of particles, of which only those near its plane are candidates.
// Particles removed without a rebuild: the others keep exactly the candidates a build over them
// gives, and the active list is renumbered.
TEST(BarrierBroadphase, CompactedCandidatesAreTheBuildOfTheParticlesLeft) {
  const Cloud c = barrier_cloud();
  const Barriers b = test_barriers();
  BarrierBroadphase bp;
  bp.build(c.x, c.r, b, kR0);
  const std::uint64_t generation = bp.generation();
  std::vector<char> keep(c.x.size(), 1);
  for (std::size_t i = 0; i < keep.size(); i += 3) keep[i] = 0;
  bp.compact(keep);
  Cloud left;
  for (std::size_t i = 0; i < keep.size(); ++i)
    if (keep[i]) {
      left.x.push_back(c.x[i]);
      left.r.push_back(c.r[i]);
    }
  BarrierBroadphase fresh;
  fresh.build(left.x, left.r, b, kR0);
  EXPECT_EQ(bp.offsets(), fresh.offsets());
  EXPECT_EQ(bp.indices(), fresh.indices());
  EXPECT_EQ(bp.active(), fresh.active());
  EXPECT_GT(bp.active().size(), 100u);
  EXPECT_NE(bp.generation(), generation) << "the store's layout must follow";
}

TEST(BarrierBroadphase, SlantedElementListsOnlyParticlesNearIt) {
  Barriers b;
  b.add(0, {0.0, 0.0, 0.0}, {0.1, 0.0, 0.1}, {0.0, 0.1, 0.1}, 0, 1e9, 0.3, {}, 0.0, 300.0);
  Cloud c;
  const double r = 0.001, skin = 0.0002;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j)
      for (int k = 0; k < 20; ++k) {
        c.x.push_back({0.005 * i, 0.005 * j, 0.005 * k});
        c.r.push_back(r);
      }
  BarrierBroadphase bp;
  bp.build(c.x, c.r, b, skin);
  const auto got = candidate_lists(bp);
  std::size_t listed = 0;
  for (std::size_t i = 0; i < got.size(); ++i) {
    const Vec3& p = c.x[i];
    const double d = norm(closest_point_on_triangle(p, b.vertex(0, 0), b.vertex(0, 1), b.vertex(0, 2)).point - p);
    listed += got[i].size();
    if (d <= r + skin) {
      EXPECT_EQ(got[i].size(), 1u) << i;
    } else if (d > (r + skin) * (1 + 1e-6)) {
      EXPECT_TRUE(got[i].empty()) << i << " at distance " << d;
    }
  }
  EXPECT_GT(listed, 0u);
  EXPECT_LT(listed, 8000u / 10);  // the box holds all 8000 centres
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
