// A sphere sliding, rolling and resting on triangulated barriers through the whole engine, against
// closed forms (physics.md sections 5-7): 5/7 v0 and 5/7 g sin(a), rolling resistance, seams.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "interact/interactions.hpp"
#include "sim/simulation.hpp"
#include "support/barrier_mechanics_scene.hpp"
#include "support/contact_scenes.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;
using namespace mpdem::test;  // kR, kE, kNu, kG, kRho, kPi, sphere_mass, E_star, name, base_scene

namespace {

// A sphere resting at its Hertz equilibrium overlap on a large flat mesh (side 0.6 m, 12 x 12
// cells), gravity on; the barrier has the particles' modulus.
Scene resting_on_floor(Integrator integ, double dt, const Vec3& x, const Vec3& v, const Vec3& w, double mu_r,
                       double xi_t) {
  Scene s = base_scene(integ, dt, {0.0, 0.0, -kG});
  test::add_flat_square(s.barriers, "floor", {0.25, 0.0, 0.0}, 0.6, 12, kE, kNu);
  ContactLawParams& c = s.model.params.contact.particle_barrier;
  c.restitution = 0.5;
  c.mu_static = 0.4;
  c.mu_dynamic = 0.3;
  c.mu_rolling = mu_r;
  c.tangential_damping = xi_t;
  const double d = test::hertz_rest_overlap(sphere_mass(kR) * kG, E_star(kE, kNu), kR);
  test::add_particle(s, 1, kR, {x.x, x.y, kR - d}, v, w);
  return s;
}

}  // namespace

// Launched sliding without spin: Coulomb friction mu_d m g decelerates v and spins the sphere
// up until v = R w, at t = 2 v0 / (7 mu_d g) with v = 5/7 v0 (both within 1%); it then keeps
// rolling at 5/7 v0 (within 1%, no rolling resistance).
TEST(RollingOnBarrier, SlidingBecomesRollingAtFiveSevenths) {
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const double v0 = 1.0, mu_d = 0.3, dt = 2e-5;
    Scene s = resting_on_floor(integ, dt, {0, 0, 0}, {v0, 0, 0}, {}, 0.0, 0.3);
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    Particles& p = sim.particles();
    const double t_exp = 2.0 * v0 / (7.0 * mu_d * kG), v_exp = 5.0 / 7.0 * v0;
    double slip_prev = v0, t_roll = -1.0, v_roll = 0.0;
    while (sim.time() < 2.0 * t_exp) {
      const double vx_prev = p.v[0].x;
      sim.advance(dt);
      const double slip = p.v[0].x - kR * p.w[0].y;  // contact-point velocity along x
      if (t_roll < 0.0 && slip <= 0.0) {
        const double f = slip_prev / (slip_prev - slip);  // linear interpolation inside the step
        t_roll = sim.time() - dt + f * dt;
        v_roll = vx_prev + f * (p.v[0].x - vx_prev);
      }
      slip_prev = slip;
    }
    std::printf("[%s] pure rolling at t %.6f (exp %.6f, err %.2e), v %.6f (exp %.6f, err %.2e), v(2t) %.6f\n",
                name(integ), t_roll, t_exp, t_roll / t_exp - 1, v_roll, v_exp, v_roll / v_exp - 1, p.v[0].x);
    EXPECT_NEAR(t_roll / t_exp, 1.0, 0.01);
    EXPECT_NEAR(v_roll / v_exp, 1.0, 0.01);
    EXPECT_NEAR(p.v[0].x / v_exp, 1.0, 0.01);
  }
}

// Rolling resistance (71) on a barrier: torque mu_r R |f_n| = mu_r R m g opposing w. With the
// rolling constraint v = R w: m dv/dt = -F, I dw/dt = F R - mu_r R m g, I = 2/5 m R^2
// => dv/dt = -mu_r g / (1 + 2/5) = -5/7 mu_r g. From v0 the sphere stops after
// t = 7 v0 / (5 mu_r g) over the distance v0^2 / (2 * 5/7 mu_r g) = 7 v0^2 / (10 mu_r g) (the
// issue's closed form is this distance). Both within 2%.
TEST(RollingOnBarrier, RollingResistanceStoppingDistance) {
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const double v0 = 0.3, mu_r = 0.1, dt = 2e-5;
    Scene s = resting_on_floor(integ, dt, {0, 0, 0}, {v0, 0, 0}, {0, v0 / kR, 0}, mu_r, 0.3);
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    Particles& p = sim.particles();
    const double t_exp = 7.0 * v0 / (5.0 * mu_r * kG), s_exp = 7.0 * v0 * v0 / (10.0 * mu_r * kG);
    double t_stop = -1.0, s_stop = 0.0;
    while (sim.time() < 1.5 * t_exp) {
      const double vx_prev = p.v[0].x, x_prev = p.x[0].x;
      sim.advance(dt);
      if (p.v[0].x <= 0.0) {  // interpolate the zero crossing of v inside the step
        const double f = vx_prev / (vx_prev - p.v[0].x);
        t_stop = sim.time() - dt + f * dt;
        s_stop = x_prev + f * (p.x[0].x - x_prev);
        break;
      }
    }
    std::printf("[%s] stop at t %.6f (exp %.6f, err %.2e), distance %.6f (exp %.6f, err %.2e)\n", name(integ), t_stop,
                t_exp, t_stop / t_exp - 1, s_stop, s_exp, s_stop / s_exp - 1);
    EXPECT_NEAR(t_stop / t_exp, 1.0, 0.02);
    EXPECT_NEAR(s_stop / s_exp, 1.0, 0.02);
  }
}

// Incline at 20 degrees (tan 20 = 0.36 < 3.5 mu_s = 1.75): the sphere rolls without slipping,
// acceleration 5/7 g sin(a) within 1% (measured from the downhill velocity between 0.05 s and
// 0.15 s, after the spring has built up).
TEST(RollingOnBarrier, InclineAccelerationFiveSevenths) {
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const double a = 20.0 * kPi / 180.0, dt = 2e-5;
    Scene s = base_scene(integ, dt, {0.0, 0.0, -kG});
    test::add_incline(s.barriers, "incline", a, 0.5, 0.1, 10, kE, kNu);
    ContactLawParams& c = s.model.params.contact.particle_barrier;
    c.restitution = 0.5;
    c.mu_static = 0.5;
    c.mu_dynamic = 0.4;
    c.tangential_damping = 0.3;
    const Vec3 down{std::cos(a), 0.0, -std::sin(a)}, nrm{std::sin(a), 0.0, std::cos(a)};
    const double d = test::hertz_rest_overlap(sphere_mass(kR) * kG * std::cos(a), E_star(kE, kNu), kR);
    test::add_particle(s, 1, kR, 0.05 * down + Vec3{0.0, 0.0013, 0.0} + (kR - d) * nrm);
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    Particles& p = sim.particles();
    double v1 = 0.0;
    while (sim.time() < 0.15 - 0.5 * dt) {
      sim.advance(dt);
      if (std::abs(sim.time() - 0.05) < 0.5 * dt) v1 = dot(p.v[0], down);
    }
    const double acc = (dot(p.v[0], down) - v1) / 0.1, exp = 5.0 / 7.0 * kG * std::sin(a);
    const double slip = norm(p.v[0] + cross(p.w[0], -kR * nrm)) / norm(p.v[0]);
    std::printf("[%s] incline acceleration %.6f (exp %.6f, err %.2e), relative slip %.1e\n", name(integ), acc, exp,
                acc / exp - 1, slip);
    EXPECT_NEAR(acc / exp, 1.0, 0.01);
    EXPECT_LT(slip, 1e-3);
  }
}

// Seam: a sphere settling (e = 0.1) onto a 4 x 4-cell square (32 triangles) exactly over its
// centre vertex, shared by 6 triangles, feels one contact and the floor carries exactly its
// weight (1e-6 relative).
TEST(Seams, WeightOverSixTriangleVertex) {
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const double dt = 2e-5;
    Scene s = base_scene(integ, dt, {0.0, 0.0, -kG});
    ASSERT_EQ(test::add_flat_square(s.barriers, "floor", {}, 0.04, 4, kE, kNu), 32);
    s.model.params.contact.particle_barrier.restitution = 0.1;
    const double m = sphere_mass(kR);
    const double d = test::hertz_rest_overlap(m * kG, E_star(kE, kNu), kR);
    test::add_particle(s, 1, kR, {0.0, 0.0, kR + 0.5 * d});  // released above the rest height
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    int max_contacts = 0;
    while (sim.time() < 0.1) {
      sim.advance(dt);
      max_contacts = std::max(max_contacts, static_cast<int>(sim.interactions().stats().contacts_pb));
    }
    const Vec3 F = test::group_force(sim.barriers(), "floor");
    const double err = std::abs(-F.z / (m * kG) - 1.0);
    std::printf("[%s] vertex seam: floor force / weight - 1 = %.2e, |F_xy| %.1e N, contacts <= %d, z err %.2e\n",
                name(integ), err, std::hypot(F.x, F.y), max_contacts, (sim.particles().x[0].z - (kR - d)) / d);
    EXPECT_LT(err, 1e-6);
    EXPECT_LT(std::hypot(F.x, F.y), 1e-9 * m * kG);
    EXPECT_EQ(max_contacts, 1);
    EXPECT_NEAR(sim.particles().x[0].z, kR - d, 1e-5 * d);  // rests at the one-triangle Hertz overlap
  }
}

// Seam: a sphere rolling (with rolling resistance, so its tangential spring carries a load of
// 5/7 mu_r m g) obliquely across a 16 x 16-cell mesh. Its speed decreases linearly; the second
// difference of the speed between consecutive steps stays below 1e-6 of the speed, across every
// seam crossing (counted from the element carrying the load).
TEST(Seams, RollingAcrossSeamsHasNoSpeedJumps) {
  const double dt = 2e-5, v0 = 0.3, mu_r = 0.02;
  const Vec3 dir{std::cos(0.5), std::sin(0.5), 0.0};
  Scene s = base_scene(Integrator::Verlet, dt, {0.0, 0.0, -kG});
  test::add_flat_square(s.barriers, "floor", {}, 0.32, 16, kE, kNu);
  ContactLawParams& c = s.model.params.contact.particle_barrier;
  c.restitution = 0.5;
  c.mu_rolling = mu_r;
  c.tangential_damping = 0.5;
  const double d = test::hertz_rest_overlap(sphere_mass(kR) * kG, E_star(kE, kNu), kR);
  const Vec3 x0 = Vec3{-0.12, -0.07, kR - d};
  test::add_particle(s, 1, kR, x0, v0 * dir, (v0 / kR) * cross({0, 0, 1}, dir));
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  Particles& p = sim.particles();
  std::vector<double> speed;
  int seams = 0;
  long last_elem = -1;
  while (sim.time() < 0.6) {
    sim.advance(dt);
    if (sim.time() < 0.1) continue;  // spring build-up transient
    speed.push_back(norm(p.v[0]));
    long elem = -1;
    for (std::size_t e = 0; e < sim.barriers().size(); ++e)
      if (norm2(sim.barriers().force[e]) > 0.0) elem = static_cast<long>(e);
    if (last_elem >= 0 && elem != last_elem) ++seams;
    last_elem = elem;
  }
  double worst = 0.0;
  for (std::size_t k = 1; k + 1 < speed.size(); ++k)
    worst = std::max(worst, std::abs(speed[k + 1] - 2.0 * speed[k] + speed[k - 1]) / speed[k]);
  const double decel = (speed.front() - speed.back()) / (dt * static_cast<double>(speed.size() - 1));
  std::printf("rolling over %d seam crossings: max |second difference| / v = %.2e; deceleration %.5f (5/7 mu_r g = "
              "%.5f)\n",
              seams, worst, decel, 5.0 / 7.0 * mu_r * kG);
  EXPECT_GE(seams, 10);
  EXPECT_LT(worst, 1e-6);
  EXPECT_NEAR(decel / (5.0 / 7.0 * mu_r * kG), 1.0, 0.01);
}
