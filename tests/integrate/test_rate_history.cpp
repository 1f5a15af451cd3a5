// The trapezoidal predictor's history (integrate/rate_history.hpp): the previous step's start
// rates follow their particles by id, and a reordering between steps leaves a run unchanged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "integrate/rate_history.hpp"
#include "sim/simulation.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;

TEST(RateHistory, FollowsParticlesById) {
  RateHistory h;
  const std::vector<std::int64_t> id{10, 20, 30};
  std::vector<Vec3> a{{1, 0, 0}, {2, 0, 0}, {3, 0, 0}}, b{{0, 1, 0}, {0, 2, 0}, {0, 3, 0}};
  const std::vector<Vec3> now{{5, 0, 0}, {6, 0, 0}, {7, 0, 0}};
  EXPECT_FALSE(h.align(id, now, now));  // nothing remembered: no extrapolation
  h.remember(id, a, b, 1e-6);
  EXPECT_EQ(h.dt(), 1e-6);
  ASSERT_TRUE(h.align(id, now, now));
  EXPECT_EQ(h.a_prev()[1], (Vec3{2, 0, 0}));
  EXPECT_EQ(h.b_prev()[2], (Vec3{0, 3, 0}));
  // Reordered, 20 removed, 40 new (no history: its current rates, so no extrapolation).
  const std::vector<std::int64_t> id2{30, 40, 10};
  ASSERT_TRUE(h.align(id2, now, now));
  EXPECT_EQ(h.a_prev()[0], (Vec3{3, 0, 0}));
  EXPECT_EQ(h.a_prev()[1], now[1]);
  EXPECT_EQ(h.a_prev()[2], (Vec3{1, 0, 0}));
  EXPECT_EQ(h.b_prev()[0], (Vec3{0, 3, 0}));
  EXPECT_EQ(h.b_prev()[1], now[1]);
  // Records (migration, checkpoints): by id, and set back in any order.
  const std::vector<RateRecord> r = h.records();
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[0].id, 10);
  EXPECT_EQ(r[2].id, 30);
  EXPECT_EQ(r[1].a, (Vec3{2, 0, 0}));
  RateHistory g;
  g.set_records({r[2], r[0]}, 2e-6);
  EXPECT_EQ(g.dt(), 2e-6);
  ASSERT_TRUE(g.align(id2, now, now));
  EXPECT_EQ(g.a_prev()[0], (Vec3{3, 0, 0}));
  EXPECT_EQ(g.a_prev()[1], now[1]);
  EXPECT_EQ(g.a_prev()[2], (Vec3{1, 0, 0}));
  EXPECT_EQ(g.records().size(), 2u);
}

namespace {
// Three head-on pairs of 1 mm spheres along x, and a sphere flying past them at 50 m/s out of
// their reach, which changes the spatial order at the rebuilds it causes (with a small skin).
Scene pairs_scene(double dt, double skin) {
  Scene s = test::make_scene(dt, 1.0);
  s.model.params.neighbor.skin = skin;
  const double r = 1e-3;  // m
  for (int k = 0; k < 3; ++k) {
    const double x = 0.004 * k;
    test::add_particle(s, 2 * k, r, {x - 1.001 * r, 0, 0}, {0.3, 0, 0});
    test::add_particle(s, 2 * k + 1, r, {x + 1.001 * r, 0, 0}, {-0.3, 0.01 * k, 0}, {0, 0, 5.0});
  }
  test::add_particle(s, 6, r, {-0.004, 0.004, 0}, {50.0, 0, 0});
  return s;
}

std::vector<Vec3> positions_by_id(const Particles& p) {
  std::vector<Vec3> x(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) x[static_cast<std::size_t>(p.id[i])] = p.x[i];
  return x;
}
}  // namespace

// Rebuilds that reorder the particles in the middle of the impacts (small skin) against none
// (a skin larger than the run's motion): the history follows the particles, so the predictor,
// the iteration counts and the states are the same (one contact per particle: the force sums
// do not depend on the order either).
TEST(RateHistory, ReorderingRebuildsChangeNothing) {
  const double dt = 2e-6;  // s
  Simulation still(pairs_scene(dt, 0.05), RunOptions{{}, false, false});
  Simulation moving(pairs_scene(dt, 2e-5), RunOptions{{}, false, false});
  bool reordered = false;
  for (int k = 0; k < 150; ++k) {
    const std::vector<std::int64_t> before = moving.particles().id;
    still.advance(dt);
    moving.advance(dt);
    reordered = reordered || moving.particles().id != before;
  }
  ASSERT_TRUE(reordered) << "the rebuilds should reorder the particles";
  EXPECT_EQ(still.interactions().stats().rebuilds, 1.0);     // the first build only
  EXPECT_GT(still.interactions().stats().contacts_pp, 0.0);  // pairs still in contact at the end
  EXPECT_EQ(moving.interactions().stats().contacts_pp, still.interactions().stats().contacts_pp);
  EXPECT_EQ(moving.evaluations(), still.evaluations());
  const std::vector<Vec3> a = positions_by_id(still.particles()), b = positions_by_id(moving.particles());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]) << "id " << i;
}
