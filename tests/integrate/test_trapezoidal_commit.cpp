// The trapezoidal rule's commit (docs/integrators.md, "Commit"): the last iteration's evaluation,
// at y_(K-1), whose rates gave the accepted y_K, stands for the commit evaluation at y_K where a
// commit's rules would not differ. It saves the commit's evaluation and moves the trajectory by
// no more than the iteration's tolerance allows; where it cannot stand in (rolling resistance)
// nothing changes, bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "sim/simulation.hpp"
#include "support/contact_scenes.hpp"
#include "support/dense_granular_scene.hpp"

using namespace mpdem;

namespace {

// A settling frictional pack in a box: sliding and sticking contacts, with walls; mu_s > mu_d,
// so a free test after a kept decision can reverse it.
Scene pack(double mu_r) {
  Scene s = test::dense_scene(4, 4, 4, 1e-3, 0.05, 2.1e-3, 0.3, 7, 2e-6);
  s.model.params.time.integrator = Integrator::Trapezoidal;
  s.model.params.time.phi = 0.5;
  for (ContactLawParams* c : {&s.model.params.contact.particle_particle, &s.model.params.contact.particle_barrier}) {
    c->mu_static = 0.5;
    c->mu_dynamic = 0.4;
    c->mu_rolling = mu_r;
  }
  return s;
}

bool same_bits(const void* a, const void* b, std::size_t n) { return std::memcmp(a, b, n) == 0; }

struct Outcome {
  Particles p;
  InteractionStats stats;
  std::uint64_t evaluations = 0;
};

Outcome run(double mu_r, bool stand_in, int steps) {
  Scene s = pack(mu_r);
  const double dt = s.model.params.time.dt;
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  sim.trapezoidal().stand_in_commits(stand_in);
  sim.initialize();
  for (int k = 0; k < steps; ++k) sim.advance(dt);
  return {sim.particles(), sim.interactions().stats(), sim.evaluations()};
}

}  // namespace

TEST(TrapezoidalCommit, RollingResistanceKeepsTheCommitEvaluationBitForBit) {
  constexpr int kSteps = 300;
  const Outcome with = run(0.05, true, kSteps), without = run(0.05, false, kSteps);
  const Particles &a = with.p, &b = without.p;
  ASSERT_EQ(a.size(), b.size());
  EXPECT_TRUE(same_bits(a.x.data(), b.x.data(), a.size() * sizeof(Vec3)));
  EXPECT_TRUE(same_bits(a.v.data(), b.v.data(), a.size() * sizeof(Vec3)));
  EXPECT_TRUE(same_bits(a.w.data(), b.w.data(), a.size() * sizeof(Vec3)));
  EXPECT_TRUE(same_bits(a.force.data(), b.force.data(), a.size() * sizeof(Vec3)));
  EXPECT_TRUE(same_bits(a.torque.data(), b.torque.data(), a.size() * sizeof(Vec3)));
  EXPECT_EQ(with.stats.friction_dissipated, without.stats.friction_dissipated);
  EXPECT_EQ(with.evaluations, without.evaluations);
}

TEST(TrapezoidalCommit, StandInSavesTheCommitAndStaysWithinTheTolerance) {
  constexpr int kSteps = 400;
  const Outcome with = run(0.0, true, kSteps), without = run(0.0, false, kSteps);
  const Particles &a = with.p, &b = without.p;
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GT(with.stats.contacts_pp, 0u);
  ASSERT_GT(with.stats.contacts_pb, 0u);
  const Scene s = pack(0.0);
  // Largest difference of the two runs' positions and velocities, against what the particles
  // moved and changed speed over the run (the scale of the iteration's relative tolerances).
  double dx = 0.0, dv = 0.0, moved = 0.0, sped = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a.id[i], b.id[i]);
    const std::size_t k = test::index_of(s.particles, a.id[i]);
    dx = std::max(dx, norm(a.x[i] - b.x[i]));
    dv = std::max(dv, norm(a.v[i] - b.v[i]));
    moved = std::max(moved, norm(a.x[i] - s.particles.x[k]));
    sped = std::max(sped, norm(a.v[i] - s.particles.v[k]));
  }
  std::printf("%llu evaluations standing in, %llu with a commit evaluation every step; max |dx| %.3g m of %.3g m "
              "moved, max |dv| %.3g m/s of %.3g m/s\n",
              static_cast<unsigned long long>(with.evaluations), static_cast<unsigned long long>(without.evaluations),
              dx, moved, dv, sped);
  // Most steps save their commit evaluation (a reversed stick/slip decision or a two-cycle keeps it).
  EXPECT_LT(with.evaluations + kSteps / 2, without.evaluations);
  // Each step's end rates differ from the commit's by the iteration's contraction times its
  // change, within the relative tolerance (1e-8): after 400 steps of a colliding pack the two
  // trajectories still agree to that tolerance of what the particles moved (measured: 3e-11).
  EXPECT_LT(dx, 1e-8 * moved);
  EXPECT_LT(dv, 1e-8 * sped);
  const double scale = std::abs(without.stats.damping_dissipated) + std::abs(without.stats.friction_dissipated);
  EXPECT_LT(std::abs(with.stats.damping_dissipated - without.stats.damping_dissipated), 1e-8 * scale);
  EXPECT_LT(std::abs(with.stats.friction_dissipated - without.stats.friction_dissipated), 1e-8 * scale);
}
