// Adaptive time stepping (physics.md section 10): the step factor's fixed points, and a sequence
// of collisions run adaptively against a fixed small-step reference.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "integrate/adaptive_step.hpp"
#include "core/run_error.hpp"
#include "sim/simulation.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;

TEST(StepFactor, OneAtTheDesiredIterationCountAndTolerance) {
  for (double eps0 : {1e-2, 3e-4, 0.5}) {
    for (int kd : {4, 10, 15}) {
      EXPECT_EQ(step_factor(1e-6, eps0, 1e-6, kd, kd, 2.0), 1.0) << eps0 << " " << kd;
    }
  }
}

TEST(StepFactor, AboveOneWhenFasterBelowWhenSlower) {
  // Converging at K < K_D with the same final error: grow.
  EXPECT_GT(step_factor(1e-6, 1e-2, 1e-6, 5, 10, 2.0), 1.0);
  // Reaching the tolerance only at K > K_D: shrink.
  EXPECT_LT(step_factor(1e-6, 1e-2, 1e-6, 14, 10, 2.0), 1.0);
  // Not converged at K_D: shrink.
  EXPECT_LT(step_factor(1e-6, 1e-2, 1e-5, 10, 10, 2.0), 1.0);
  // Guards: an exact first iterate gives the largest growth; the factor stays in its range.
  EXPECT_EQ(step_factor(1e-6, 0.0, 0.0, 1, 10, 2.0), kMaxFactor);
  EXPECT_EQ(step_factor(1e-12, 1.0, 1.0, 1, 10, 2.0), kMinFactor);
}

namespace {
// A sphere bouncing on a floor (e = 0.8) under gravity: a sequence of collisions separated by
// free flight, where a fixed step is wasted on the flights and an adaptive one is not.
Scene collision_scene(double dt, bool adaptive, double tol = 1e-6) {
  Scene s = test::make_scene(dt, 0.2);
  Params& prm = s.model.params;
  prm.time.phi = 0.5;
  prm.time.adaptive = adaptive;
  prm.time.dt_max = 2e-3;
  prm.time.dt_min = 1e-9;
  prm.time.desired_iterations = 4;
  prm.tolerance.position = prm.tolerance.velocity = prm.tolerance.rotation = prm.tolerance.angular_velocity = tol;
  prm.contact.particle_barrier.restitution = 0.8;
  prm.checks.max_overlap = 0.1;  // the soft sphere's impact overlap (~5.6% of R) is physical here
  test::add_particle(s, 1, 0.005, {0.0, 0.0, 0.025}, {0.0, 0.0, 0.0});
  const int g = s.barriers.group_index("floor");
  s.barriers.add(1, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, g, 1e7, 0.3, {}, 0.0, NAN);
  s.barriers.add(2, {-1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, g, 1e7, 0.3, {}, 0.0, NAN);
  return s;
}

struct Outcome {
  std::vector<Vec3> x, v;
  std::uint64_t evaluations = 0;
  std::uint64_t redone = 0;
};

Outcome run(double dt, bool adaptive, double tol = 1e-6) {
  Scene s = collision_scene(dt, adaptive, tol);
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  const double end = sim.model().params.time.duration;
  while (sim.time() < end - 1e-15) {
    if (adaptive) sim.advance_adaptive(end - sim.time());
    else sim.advance(std::min(dt, end - sim.time()));
  }
  return {sim.particles().x, sim.particles().v, sim.evaluations(), sim.redone_steps()};
}

double velocity_error(const Outcome& a, const Outcome& ref) {
  double e = 0.0;
  for (std::size_t i = 0; i < a.v.size(); ++i) e = std::max(e, norm(a.v[i] - ref.v[i]));
  return e / 0.63;  // relative to the first impact speed sqrt(2 g h)
}
}  // namespace

TEST(AdaptiveStepping, CollisionSequenceMatchesFixedStepWithFewerEvaluations) {
  const Outcome ref = run(2e-6, false);
  const Outcome ada = run(1e-3, true, 1e-6);
  const double err = velocity_error(ada, ref);
  std::printf("adaptive TOL 1e-6: %llu evaluations, %llu redone steps, velocity error %.3g\n",
              static_cast<unsigned long long>(ada.evaluations), static_cast<unsigned long long>(ada.redone), err);
  // The scheme bounds the contraction of the iteration, (phi dt)^2 k / m ~ (TOL/eps_0)^(1/K_D)
  // (thesis (144)-(145)), which with K_D = 4 and TOL = 1e-6 resolves a collision in ~10 steps:
  // the rebound speeds then agree with the fine reference within 1% of the impact speed.
  EXPECT_LT(err, 1e-2);
  EXPECT_GT(ada.redone, 0u);  // the step shrank at impacts
  // The largest fixed step that is as accurate costs more evaluations.
  std::uint64_t fixed_evals = 0;
  for (double dt : {1e-3, 5e-4, 2e-4, 1e-4, 5e-5, 2e-5, 1e-5, 5e-6, 2e-6}) {
    Outcome f;
    try {
      f = run(dt, false);
    } catch (const RunError&) {
      continue;  // too large to converge at all
    }
    if (velocity_error(f, ref) <= err) {
      fixed_evals = f.evaluations;
      std::printf("fixed dt %.3g s of equal accuracy: %llu evaluations (error %.3g)\n", dt,
                  static_cast<unsigned long long>(f.evaluations), velocity_error(f, ref));
      break;
    }
  }
  ASSERT_GT(fixed_evals, 0u);
  EXPECT_LT(ada.evaluations, fixed_evals);
}

TEST(AdaptiveStepping, FailureAtMinimumStepNamesTheParticle) {
  Scene s = collision_scene(1e-3, true);
  s.model.params.time.dt_min = 1e-3;  // cannot shrink
  s.model.params.time.dt_max = 1e-3;
  s.model.params.time.desired_iterations = 2;
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  try {
    for (int k = 0; k < 200; ++k) sim.advance_adaptive(1.0);
    FAIL() << "expected a RunError";
  } catch (const RunError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("time.dt_min"), std::string::npos) << msg;
    EXPECT_NE(msg.find("particle id"), std::string::npos) << msg;
  }
}
