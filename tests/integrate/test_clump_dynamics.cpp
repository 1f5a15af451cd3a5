// Rigid clumps in motion (docs/physics.md "Clumps"), both integrators where it says: a one-member clump follows
// the sphere's trajectory; a dumbbell on an incline rolls (mu above the rolling limit) or slides
// (below) with the closed-form accelerations; the restitution of n simultaneous member contacts
// follows the documented damping-mass rule; a body's members never touch each other; the run does
// not depend on the thread count.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "physics/restitution.hpp"
#include "sim/simulation.hpp"
#include "support/clump_scenes.hpp"
#include "support/dense_granular_scene.hpp"

using namespace mpdem;
using namespace mpdem::test;

namespace {

constexpr double kR = 1e-3;   // m
constexpr double kDt = 2e-6;  // s, about the Rayleigh time / 40 for the default material (E = 1e7 Pa)

Scene clump_scene(double mu, double duration, Integrator integ = Integrator::Verlet) {
  Scene s = make_scene(kDt, duration);
  s.model.params.time.integrator = integ;
  s.model.params.time.phi = 0.5;
  set_contact_law(s, mu);
  s.model.params.checks.max_overlap = 0.2;
  s.model.params.fields.gravity = {};  // tests that want it set it
  return s;
}

double rel(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }

// The largest difference of x, v and w between two runs' particles, relative to the scales
// (m, m/s, rad/s) of the case.
double trajectory_difference(const Particles& a, const Particles& b, double x_scale, double v_scale, double w_scale) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    d = std::max(d, norm(a.x[i] - b.x[i]) / x_scale);
    d = std::max(d, norm(a.v[i] - b.v[i]) / v_scale);
    d = std::max(d, norm(a.w[i] - b.w[i]) / w_scale);
  }
  return d;
}

struct Impact {
  Vec3 x, v, w;  // first body's (m, m/s, rad/s)
  bool pair;     // a second one, mirrored through the origin, instead of the floor
};

Particles run_impact(const Impact& c, bool clumps, int steps, Integrator integ) {
  Scene s = clump_scene(0.3, 1.0, integ);
  const int one = add_template(s, "one", {{{0.0, 0.0, 0.0}, kR}});
  const auto add = [&](std::int64_t id, const Vec3& x, const Vec3& v, const Vec3& w) {
    if (clumps) add_clump(s, id, one, x, v, w);
    else add_particle(s, id, kR, x, v, w);
  };
  add(1, c.x, c.v, c.w);
  if (c.pair) add(2, -1.0 * c.x, -1.0 * c.v, -1.0 * c.w);
  else add_floor(s, 0.0, 0.05);
  if (clumps) finish_clumps(s);
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  for (int k = 0; k < steps; ++k) sim.advance(kDt);
  Particles p = sim.particles();
  p.sort_by_id();
  return p;
}

}  // namespace

TEST(ClumpDynamics, OneMemberClumpFollowsTheSphere) {
  // The validation suite's impacts: normal and oblique on a plane, with spin, and a sphere pair.
  const std::vector<Impact> cases = {{{0, 0, 1.05 * kR}, {0, 0, -0.5}, {}, false},
                                     {{0, 0, 1.05 * kR}, {0.4, 0, -0.3}, {}, false},
                                     {{0, 0, 1.05 * kR}, {0.1, 0, -0.3}, {0, 300, 50}, false},
                                     {{1.02 * kR, 0.3 * kR, 0}, {-0.4, 0, 0}, {0, 0, 100}, true}};
  for (const Impact& c : cases)
    for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
      const Particles spheres = run_impact(c, false, 3000, integ), clumps = run_impact(c, true, 3000, integ);
      ASSERT_EQ(spheres.size(), clumps.size());
      // A contact happened: the velocity changed.
      EXPECT_GT(norm(spheres.v[0] - c.v), 0.1 * norm(c.v));
      EXPECT_LT(trajectory_difference(clumps, spheres, kR, norm(c.v), norm(c.v) / kR), 1e-12)
          << "impact v = " << c.v.x << ", " << c.v.y << ", " << c.v.z
          << (integ == Integrator::Verlet ? " verlet" : " trapezoidal");
    }
}

namespace {

// A dumbbell (two touching spheres of radius r, axis across the slope) on a plane inclined by
// theta: gravity tilted instead of the plane. Returns the centre of mass's acceleration along the
// slope (m/s^2), and its spin about the axis times r over its speed, from the velocity change
// between t1 and t2 after the contact transient.
struct SlopeMotion {
  double a;        // m/s^2
  double rolling;  // -, w r / v: 1 rolling without slip
};

SlopeMotion dumbbell_on_incline(double mu, double theta, Integrator integ) {
  const double g = 9.81, t1 = 0.02, t2 = 0.05;
  Scene s = clump_scene(mu, t2, integ);
  s.model.params.fields.gravity = {g * std::sin(theta), 0.0, -g * std::cos(theta)};
  const int db = add_template(s, "dumbbell", {{{0.0, -kR, 0.0}, kR}, {{0.0, kR, 0.0}, kR}});
  add_clump(s, 1, db, {0.0, 0.0, kR});
  add_floor(s, 0.0, 0.5);
  finish_clumps(s);
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  const auto steps = [](double t) { return static_cast<int>(std::lround(t / kDt)); };
  for (int k = 0; k < steps(t1); ++k) sim.advance(kDt);
  const double v1 = sim.particles().bodies.v[0].x;
  for (int k = steps(t1); k < steps(t2); ++k) sim.advance(kDt);
  const Bodies& B = sim.particles().bodies;
  return {(B.v[0].x - v1) / (t2 - t1), B.w[0].y * kR / B.v[0].x};
}

}  // namespace

TEST(ClumpDynamics, DumbbellRollsOrSlidesDownAnIncline) {
  const double g = 9.81, theta = 20.0 * std::numbers::pi / 180.0;
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    SCOPED_TRACE(integ == Integrator::Verlet ? "verlet" : "trapezoidal");
    // Rolling without slip: a = g sin(theta) / (1 + I/(M r^2)) with I = 0.4 M r^2 about the axis.
    const SlopeMotion roll = dumbbell_on_incline(0.3, theta, integ);
    EXPECT_LT(rel(roll.a, g * std::sin(theta) / 1.4), 1e-3) << roll.a;
    EXPECT_NEAR(roll.rolling, 1.0, 1e-3);
    // Below the rolling limit tan(theta) 0.4 / 1.4 = 0.104 it slides: a = g (sin - mu cos).
    const double mu = 0.05;
    ASSERT_LT(mu, std::tan(theta) * 0.4 / 1.4);
    const SlopeMotion slide = dumbbell_on_incline(mu, theta, integ);
    EXPECT_LT(rel(slide.a, g * (std::sin(theta) - mu * std::cos(theta))), 1e-3) << slide.a;
    EXPECT_LT(slide.rolling, 0.9);
  }
}

namespace {

// Restitution of a body of `members` falling flat (no gravity) on the floor at 0.5 m/s, all its
// lowest members touching at once.
double floor_restitution(const std::vector<ClumpMember>& members) {
  Scene s = clump_scene(0.0, 1.0);
  const int c = add_template(s, "shape", members);
  const double v0 = 0.5;
  add_clump(s, 1, c, {0.0, 0.0, 1.001 * kR}, {0.0, 0.0, -v0});
  add_floor(s, 0.0, 0.05);
  finish_clumps(s);
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  for (int k = 0; k < 3000; ++k) sim.advance(kDt);
  const Bodies& B = sim.particles().bodies;
  EXPECT_LT(norm(B.w[0]), 1e-9);  // symmetric: no turn
  return B.v[0].z / v0;
}

}  // namespace

TEST(ClumpDynamics, RestitutionOfSimultaneousMemberContacts) {
  // Each member contact's damping mass is the body's mass M (docs/physics.md "Clumps: contacts").
  // n equal simultaneous contacts on M move like one contact on M/n whose damping ratio is
  // sqrt(n) times the calibrated one (the damping scales with sqrt(m*)): the restitution is
  // e_n = restitution_for_damping_ratio(sqrt(n) xi(e)) - exact for n = 1, lower for n > 1.
  const double e = 0.5, xi = damping_ratio_for_restitution(e);
  const std::vector<std::vector<ClumpMember>> shapes = {
      {{{0, 0, 0}, kR}},                                                                  // 1 contact
      {{{-kR, 0, 0}, kR}, {{kR, 0, 0}, kR}},                                              // 2: a flat dumbbell
      {{{-kR, -kR, 0}, kR}, {{kR, -kR, 0}, kR}, {{-kR, kR, 0}, kR}, {{kR, kR, 0}, kR}}};  // 4: a flat square
  const std::vector<int> n = {1, 2, 4};
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    const double measured = floor_restitution(shapes[k]);
    const double expected = restitution_for_damping_ratio(std::sqrt(static_cast<double>(n[k])) * xi);
    EXPECT_LT(rel(measured, expected), 0.01) << n[k] << " contacts: e = " << measured << ", rule " << expected;
    std::printf("clump restitution, %d simultaneous contact(s): e = %.4f (rule %.4f, sphere %.2f)\n", n[k], measured,
                expected, e);
  }
}

TEST(ClumpDynamics, MembersOfOneBodyNeverInteract) {
  // Overlapping members (centres r apart) at rest, no gravity: no force within the body.
  Scene s = clump_scene(0.5, 1.0);
  const int c = add_template(s, "lens", {{{0, 0, 0}, kR}, {{kR, 0, 0}, kR}, {{0.5 * kR, kR, 0}, kR}});
  add_clump(s, 1, c, {0.0, 0.0, 0.0});
  finish_clumps(s);
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  for (int k = 0; k < 10; ++k) sim.advance(kDt);
  const Particles& p = sim.particles();
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_EQ(norm(p.force[i]), 0.0);
  EXPECT_EQ(norm(p.bodies.v[0]), 0.0);
}

namespace {

// Tetrahedral clumps dropped into a box in a heap: the bodies' states after `steps`.
Bodies clump_pile(int threads, int steps) {
  omp_set_num_threads(threads);
  Scene s = clump_scene(0.5, 1.0);
  s.model.params.fields.gravity = {0.0, 0.0, -9.81};
  const double a = 0.7 * kR;
  const int tet = add_template(s, "tetra", {{{a, a, a}, kR}, {{a, -a, -a}, kR}, {{-a, a, -a}, kR}, {{-a, -a, a}, kR}});
  std::int64_t id = 1;
  // 640 bodies, 2560 members: above the size (kParallelThreshold) from which the loops run in parallel.
  for (int k = 0; k < 10; ++k)
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 8; ++i) {
        const double h = 4.2 * kR;
        const Quat q = quat_normalized({1.0, 0.1 * i, 0.2 * j, 0.3 * k});
        add_clump(s, id++, tet, {h * (i - 3.5) + 0.1 * kR * j, h * (j - 3.5), 3 * kR + h * k}, {0.01 * i, 0, 0},
                  {0, 0, 3.0 * j}, q);
      }
  add_floor(s, 0.0, 0.05);
  finish_clumps(s);
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  for (int k = 0; k < steps; ++k) sim.advance(kDt);
  omp_set_num_threads(1);
  return sim.particles().bodies;
}

}  // namespace

TEST(ClumpDynamics, ThreadCountDoesNotChangeTheRun) {
  const Bodies one = clump_pile(1, 1500), two = clump_pile(2, 1500);
  ASSERT_EQ(one.size(), two.size());
  bool moved = false;
  for (std::size_t b = 0; b < one.size(); ++b) {
    EXPECT_EQ(one.x[b].x, two.x[b].x);
    EXPECT_EQ(one.x[b].z, two.x[b].z);
    EXPECT_EQ(one.w[b].y, two.w[b].y);
    EXPECT_EQ(one.q[b].w, two.q[b].w);
    moved = moved || norm(one.force[b]) > 0.0;
  }
  EXPECT_TRUE(moved);
}
