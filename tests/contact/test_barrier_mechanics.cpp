// Particle-barrier contact mechanics through the whole engine (Simulation + Interactions +
// BarrierContacts), against closed forms (physics.md sections 5-7, 12):
//   - sphere on a (nearly rigid) barrier: Hertz peak force, overlap, contact time; restitution;
//   - sliding -> rolling at 5/7 v0 after 2 v0 / (7 mu_d g); rolling resistance stopping distance;
//   - rolling down an incline at 5/7 g sin(a);
//   - seams: weight over a 6-triangle vertex, rolling over many seams without speed jumps;
//   - a square hole: a small sphere falls through untouched, a large one rests on the rim;
//   - a settled bed of 2000 spheres in an open box: floor force = weight, energy bookkeeping;
//   - bitwise identical loads for 1 and 2 threads; history kept through a reordering rebuild.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <random>
#include <vector>

#include "core/parallel.hpp"
#include "integrate/integrator_policy.hpp"
#include "sim/energy.hpp"
#include "model/material_variants.hpp"
#include "sim/interactions.hpp"
#include "sim/simulation.hpp"
#include "support/contact_scenes.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;

namespace {

constexpr double kRho = 2500.0;  // kg/m^3
constexpr double kE = 1e7;       // Pa
constexpr double kNu = 0.3;      // -
constexpr double kR = 0.005;     // m
constexpr double kG = 9.81;      // m/s^2
const double kPi = std::acos(-1.0);

double sphere_mass(double R) { return 4.0 / 3.0 * kPi * R * R * R * kRho; }
// (51) with the barrier's own modulus, written out independently of the engine   [Pa]
double E_star(double Eb, double nub) { return kE * Eb / (Eb * (1.0 - kNu * kNu) + kE * (1.0 - nub * nub)); }
const char* name(Integrator i) { return i == Integrator::Verlet ? "verlet" : "trapezoidal"; }

Scene base_scene(Integrator integ, double dt, const Vec3& gravity) {
  Scene s = test::make_scene(dt, 1.0);
  s.model.params.time.integrator = integ;
  s.model.params.time.phi = 0.5;
  s.model.params.fields.gravity = gravity;
  s.model.params.tolerance.position = 1e-10;
  s.model.params.tolerance.velocity = 1e-10;
  test::set_material(s, kRho, kE, kNu);
  // These tests check the laws at finite overlaps: the overlap instability check would stop
  // them; it is tested in test_instability.cpp.
  s.model.params.checks.max_overlap = 0.0;
  return s;
}

struct Impact {
  double F_max = 0.0, delta_max = 0.0, t_c = 0.0;  // N, m, s
  double v_after = 0.0;                            // m/s, rebound z-velocity
  double third_law = 0.0;                          // max |f_particle + sum f_barrier| / |f|
};

// Sphere falling (no gravity) with speed v onto an 8 x 8-cell flat square in z = 0 whose
// modulus is Eb; the contact point lies inside a face away from seams.
Impact barrier_impact(Integrator integ, double v, double e, double Eb, double steps_per_tc) {
  const double m = sphere_mass(kR), Es = E_star(Eb, kNu);
  const double dmax = std::pow(15.0 * m * v * v / (16.0 * Es * std::sqrt(kR)), 0.4);
  const double dt = 2.943275 * dmax / v / steps_per_tc;
  Scene s = base_scene(integ, dt, {});
  test::add_flat_square(s.barriers, "floor", {}, 0.1, 8, Eb, kNu);
  if (e < 1.0)
    s.model.params.contact.particle_barrier.restitution = e;
  else
    s.model.params.contact.particle_barrier.damping_ratio = 0.0;
  const double gap = 3.3 * v * dt;
  test::add_particle(s, 1, kR, {0.0031, -0.0042, kR + gap}, {0.0, 0.0, -v});
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  Particles& p = sim.particles();
  Impact r;
  double ov_prev = -gap, t_start = -1.0;
  for (int k = 0; k < 20 * static_cast<int>(steps_per_tc); ++k) {
    sim.advance(dt);
    const double ov = kR - p.x[0].z, t = sim.time();
    if (ov > 0.0) {
      r.F_max = std::max(r.F_max, norm(p.force[0]));
      r.delta_max = std::max(r.delta_max, ov);
      r.third_law = std::max(r.third_law, norm(p.force[0] + test::group_force(sim.barriers(), "floor")) / norm(p.force[0]));
    }
    if (ov_prev <= 0.0 && ov > 0.0 && t_start < 0.0) t_start = t - dt * ov / (ov - ov_prev);
    if (ov_prev > 0.0 && ov <= 0.0) {
      r.t_c = (t - dt * (-ov) / (ov_prev - ov)) - t_start;
      r.v_after = p.v[0].z;
      break;
    }
    ov_prev = ov;
  }
  return r;
}

}  // namespace

// Sphere on a barrier 1e6 times stiffer than itself, e = 1: peak force and maximum overlap within
// 0.5%, contact time within 1% of the closed forms with r* = R, m* = m and E* of (51) with the
// barrier's E (and also with the rigid limit E/(1 - nu^2), 1e-6 away); elastic rebound.
TEST(SphereOnBarrier, MatchesHertzClosedForms) {
  const double m = sphere_mass(kR);
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal})
    for (double v : {0.1, 1.0}) {
      const Impact r = barrier_impact(integ, v, 1.0, 1e6 * kE, 1000.0);
      for (double Es : {E_star(1e6 * kE, kNu), kE / (1.0 - kNu * kNu)}) {
        const double dmax = std::pow(15.0 * m * v * v / (16.0 * Es * std::sqrt(kR)), 0.4);
        const double Fmax = 4.0 / 3.0 * Es * std::sqrt(kR) * std::pow(dmax, 1.5);
        const double tc = 2.943275 * dmax / v;
        std::printf("[%s v=%g E*=%.8g] F_max err %.2e, delta_max err %.2e, t_c err %.2e, e %.6f, 3rd law %.1e\n",
                    name(integ), v, Es, r.F_max / Fmax - 1, r.delta_max / dmax - 1, r.t_c / tc - 1, r.v_after / v,
                    r.third_law);
        EXPECT_NEAR(r.F_max / Fmax, 1.0, 0.005);
        EXPECT_NEAR(r.delta_max / dmax, 1.0, 0.005);
        EXPECT_NEAR(r.t_c / tc, 1.0, 0.01);
      }
      EXPECT_NEAR(r.v_after, v, 1e-4 * v);
      EXPECT_LT(r.third_law, 1e-12);  // the floor's loads are exactly the opposite of the sphere's force
    }
}

// Achieved restitution against a barrier (E_b = E) within 0.005 of e, e x speed sweep,
// dt = t_c / 200.
TEST(SphereOnBarrier, RestitutionSweep) {
  double worst = 0.0;
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal})
    for (double e : {0.1, 0.3, 0.5, 0.7, 0.9, 1.0})
      for (double v : {0.01, 0.1, 1.0, 10.0}) {
        const Impact r = barrier_impact(integ, v, e, kE, 200.0);
        worst = std::max(worst, std::abs(r.v_after / v - e));
        EXPECT_NEAR(r.v_after / v, e, 0.005) << name(integ) << " e " << e << " v " << v;
      }
  std::printf("restitution sphere-barrier: worst |e_achieved - e| = %.2e\n", worst);
}

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
    std::printf("[%s] stop at t %.6f (exp %.6f, err %.2e), distance %.6f (exp %.6f, err %.2e)\n", name(integ),
                t_stop, t_exp, t_stop / t_exp - 1, s_stop, s_exp, s_stop / s_exp - 1);
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

// A sphere of diameter d falls through the centre of a square hole of side 1.2 d in a
// triangulated plate without any contact; one of diameter 2 d settles on the hole's four rims,
// carrying its weight (1e-6) at rest, at the height where 4 Hertz edge forces balance it.
TEST(Hole, SmallSphereFallsThroughLargeOneRestsOnRim) {
  const double d = 2.0 * kR, hole = 1.2 * d;
  {
    const double dt = 2e-5;
    Scene s = base_scene(Integrator::Verlet, dt, {0.0, 0.0, -kG});
    test::add_plate_with_hole(s.barriers, "plate", 0.0, hole, kE, kNu);
    test::add_particle(s, 1, kR, {3e-4, -2e-4, 2.0 * kR}, {0.0, 0.0, -1.0});
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    std::size_t contacts = 0;
    while (sim.particles().x[0].z > -2.0 * kR) {
      sim.advance(dt);
      contacts += sim.interactions().stats().contacts_pb;
    }
    EXPECT_EQ(contacts, 0u);
    EXPECT_EQ(sim.particles().v[0].x, 0.0);
    EXPECT_EQ(sim.particles().v[0].y, 0.0);
  }
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const double R = kR * 2.0, dt = 2e-5, m = sphere_mass(R);
    Scene s = base_scene(integ, dt, {0.0, 0.0, -kG});
    test::add_plate_with_hole(s.barriers, "plate", 0.0, hole, kE, kNu);
    ContactLawParams& c = s.model.params.contact.particle_barrier;
    c.restitution = 0.1;
    c.mu_static = 0.0;  // frictionless: the rest height is then unique (with friction the springs
    c.mu_dynamic = 0.0; // keep whatever load the settling left, and the height depends on history)
    s.model.params.tolerance = ToleranceParams{};
    const double h = 0.5 * hole;
    test::add_particle(s, 1, R, {0.0, 0.0, std::sqrt(R * R - h * h) + 1e-5});
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    while (sim.time() < 0.1) sim.advance(dt);
    const Particles& p = sim.particles();
    const Vec3 F = test::group_force(sim.barriers(), "plate");
    // Rest height: 4 F_hertz(delta) z / (R - delta) = m g with z = sqrt((R - delta)^2 - h^2).
    double delta = 0.0;
    for (int it = 0; it < 200; ++it) {
      const double dist = R - delta, z = std::sqrt(dist * dist - h * h);
      delta = test::hertz_rest_overlap(m * kG * dist / (4.0 * z), E_star(kE, kNu), R);
    }
    const double z_exp = std::sqrt((R - delta) * (R - delta) - h * h);
    std::printf("[%s] rim: contacts %zu, floor force / weight - 1 = %.2e, |v| %.1e, z err / delta %.2e\n", name(integ),
                sim.interactions().stats().contacts_pb, -F.z / (m * kG) - 1.0, norm(p.v[0]), (p.x[0].z - z_exp) / delta);
    EXPECT_EQ(sim.interactions().stats().contacts_pb, 4u);
    EXPECT_NEAR(-F.z / (m * kG), 1.0, 1e-6);
    EXPECT_LT(norm(p.v[0]), 1e-6);
    EXPECT_NEAR(p.x[0].z, z_exp, 1e-3 * delta);
  }
}

// A bed of 2000 spheres (800 under ASan) (20 x 20 x 5 lattice with jitter) settles in an open box of triangles
// (Verlet, dt near the recommended step, e = 0.1, friction). Once settled the bottom group's
// vertical force equals the total weight within 1%. Energy bookkeeping
// kinetic + rotational + potential + elastic + damping + friction dissipated stays constant within
// 15% of the energy dissipated: at this coarse step (contact time / dt ~ 13) the dissipation,
// integrated per step from the evaluated powers (Verlet half-step velocities), and the
// history-dependent tangential spring energy 1/2 k_t s^2 are first-order approximations; the
// drift shrinks ~6x when dt is halved (measured), so it is discretisation, not a leak.
TEST(SettledBed, FloorCarriesWeightAndEnergyIsBookkept) {
  // dt = 1e-4 s: 0.2 x Rayleigh time is 1.1e-4 s for R = 2 mm, E = 1 MPa.
  const double R = 0.002, E = 1e6, spacing = 2.2 * R, dt = 1e-4, T_end = 0.25;
#ifdef __SANITIZE_ADDRESS__
  const int nx = 20, nz = 2;  // smaller variant under ASan (800 spheres), same physics
#else
  const int nx = 20, nz = 5;  // 2000 spheres
#endif
  const double W = nx * spacing;
  Scene s = base_scene(Integrator::Verlet, dt, {0.0, 0.0, -kG});
  test::set_material(s, kRho, E, kNu);
  test::add_open_box(s.barriers, W, 6.0 * spacing, 4, E, kNu);
  ContactLawParams& pp = s.model.params.contact.particle_particle;
  pp.restitution = 0.1;
  pp.mu_static = 0.5;
  pp.mu_dynamic = 0.4;
  pp.tangential_damping = 0.3;
  s.model.params.contact.particle_barrier = pp;
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  std::int64_t id = 0;
  for (int l = 0; l < nz; ++l)
    for (int j = 0; j < nx; ++j)
      for (int i = 0; i < nx; ++i) {
        const Vec3 x{(i + 0.5) * spacing + 0.05 * R * U(rng), (j + 0.5) * spacing + 0.05 * R * U(rng),
                     1.1 * R + l * spacing};
        test::add_particle(s, ++id, R, x, 0.05 * Vec3{U(rng), U(rng), U(rng)});
      }
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  const Vec3 g = sim.model().params.fields.gravity;
  auto total_energy = [&] {
    const ParticleEnergy pe = particle_energy(sim.particles(), g);
    const InteractionStats& st = sim.interactions().stats();
    return pe.kinetic + pe.rotational + pe.potential + st.elastic_energy + st.damping_dissipated +
           st.friction_dissipated;
  };
  sim.initialize();
  const double E0 = total_energy();
  double worst_drift = 0.0;
  while (sim.time() < T_end) {
    sim.advance(dt);
    if (sim.steps() % 50 == 0) worst_drift = std::max(worst_drift, std::abs(total_energy() - E0));
  }
  double weight = 0.0;
  for (std::size_t i = 0; i < sim.particles().size(); ++i) weight += sim.particles().mass[i] * kG;
  const Vec3 Fb = test::group_force(sim.barriers(), "bottom"), Fw = test::group_force(sim.barriers(), "walls");
  const InteractionStats& st = sim.interactions().stats();
  const double dissipated = st.damping_dissipated + st.friction_dissipated;
  const ParticleEnergy pe = particle_energy(sim.particles(), g);
  std::printf("bed: N %zu, bottom / weight - 1 = %.2e, walls vertical / weight = %.2e, (bottom+walls)/weight - 1 = "
              "%.2e, kinetic %.2e J, energy drift %.2e J of dissipated %.2e J (%.2e)\n",
              sim.particles().size(), -Fb.z / weight - 1, -Fw.z / weight, -(Fb.z + Fw.z) / weight - 1, pe.kinetic,
              worst_drift, dissipated, worst_drift / dissipated);
  EXPECT_NEAR(-Fb.z / weight, 1.0, 0.01);
  EXPECT_NEAR(-(Fb.z + Fw.z) / weight, 1.0, 2e-3);  // floor + wall friction carry it all
  EXPECT_LT(worst_drift, 0.15 * dissipated);
  EXPECT_GT(dissipated, 0.0);
}

namespace {

// A layer of nx x nx spheres on the floor of an open box (4 x 4-cell floor: seams), sliding
// and spinning with random velocities; `gap` x R between neighbours' surfaces.
Scene sliding_layer(Integrator integ, int nx, double gap, double dt) {
  const double R = 0.002, spacing = (2.0 + gap) * R, W = nx * spacing;
  Scene s = base_scene(integ, dt, {0.0, 0.0, -kG});
  test::add_open_box(s.barriers, W, 4.0 * R, 4, kE, kNu);
  ContactLawParams& c = s.model.params.contact.particle_barrier;
  c.restitution = 0.3;
  c.mu_static = 0.5;
  c.mu_dynamic = 0.3;
  c.mu_rolling = 0.02;
  c.tangential_damping = 0.3;
  s.model.params.contact.particle_particle = c;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  std::int64_t id = 0;
  for (int j = 0; j < nx; ++j)
    for (int i = 0; i < nx; ++i) {
      // Outer rows pressed slightly into the walls, so wall elements carry loads too.
      const double x = i == 0 ? 0.999 * R : (i == nx - 1 ? W - 0.999 * R : (i + 0.5) * spacing);
      const double y = j == 0 ? 0.999 * R : (j == nx - 1 ? W - 0.999 * R : (j + 0.5) * spacing);
      test::add_particle(s, ++id, R, {x, y, 0.998 * R}, 0.2 * Vec3{U(rng), U(rng), 0.0},
                         (0.2 / R) * Vec3{U(rng), U(rng), U(rng)});
    }
  return s;
}

struct Loads {
  std::vector<Vec3> bf, bm, pf, pt;  // barrier force N, moment N m; particle force N, torque N m (by index)
  std::size_t contacts_pb = 0;
};

Loads run_layer(int threads, Integrator integ) {
  omp_set_num_threads(threads);
  const double dt = 2e-5;
  Scene s = sliding_layer(integ, 50, 0.1, dt);
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  for (int k = 0; k < 40; ++k) sim.advance(dt);
  Loads l{sim.barriers().force, sim.barriers().moment, sim.particles().force, sim.particles().torque,
          sim.interactions().stats().contacts_pb};
  return l;
}

std::size_t bitwise_differences(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  if (a.size() != b.size()) return std::max(a.size(), b.size());
  std::size_t d = 0;
  for (std::size_t i = 0; i < a.size(); ++i) d += std::memcmp(&a[i], &b[i], sizeof(Vec3)) != 0;
  return d;
}

}  // namespace

// 2500 spheres against 64 triangles (floor and walls), more than kParallelThreshold of them near
// a barrier: the element loads (force, moment) and the particle forces and torques are bitwise
// identical for 1 and 2 OpenMP threads.
TEST(BarrierContactsParallel, BitwiseIdenticalForOneAndTwoThreads) {
  static_assert(50 * 50 > kParallelThreshold, "the barrier contacts must take the parallel paths");
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const Loads one = run_layer(1, integ);
    const Loads two = run_layer(2, integ);
    EXPECT_GT(one.contacts_pb, kParallelThreshold);
    std::size_t loaded = 0;
    for (const Vec3& f : one.bf) loaded += norm2(f) > 0.0;
    EXPECT_GT(loaded, 32u);  // the 32 floor elements and wall elements
    EXPECT_EQ(one.contacts_pb, two.contacts_pb);
    EXPECT_EQ(bitwise_differences(one.bf, two.bf), 0u) << name(integ);
    EXPECT_EQ(bitwise_differences(one.bm, two.bm), 0u) << name(integ);
    EXPECT_EQ(bitwise_differences(one.pf, two.pf), 0u) << name(integ);
    EXPECT_EQ(bitwise_differences(one.pt, two.pt), 0u) << name(integ);
  }
  omp_set_num_threads(omp_get_num_procs());
}

// Spheres sliding and rolling on a seamed floor and against walls, apart from each other (each
// particle's forces then come from its barrier contacts alone). After the springs have built up,
// a forced rebuild that reorders the particles, and the removal of some particles, leave the
// forces and torques of an evaluation (which uses the springs, the start-of-step tangential
// velocities and rotations) bitwise unchanged for every remaining particle; without the history
// they would differ.
TEST(BarrierContactHistory, SurvivesReorderingRebuildAndRemoval) {
  const double dt = 2e-5;
  Scene s = sliding_layer(Integrator::Trapezoidal, 12, 4.0, dt);
  const Scene fresh_scene = s;
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  // The steps reorder at every rebuild (every ~37 steps here); stopping halfway between two
  // leaves the particles far enough out of order for the forced reordering below to move them.
  for (int k = 0; k < 135; ++k) sim.advance(dt);
  Particles& p = sim.particles();
  Barriers& b = sim.barriers();
  Interactions& in = sim.interactions();
  const EvalRequest req{sim.time() + dt, dt, 0.5, false, 1};  // an iteration: uses every history field
  const auto by_id = [&p] {
    std::map<std::int64_t, std::array<Vec3, 2>> m;
    for (std::size_t i = 0; i < p.size(); ++i) m[p.id[i]] = {p.force[i], p.torque[i]};
    return m;
  };
  const auto equal = [](const std::map<std::int64_t, std::array<Vec3, 2>>& a,
                        const std::map<std::int64_t, std::array<Vec3, 2>>& c) {
    std::size_t d = 0;
    for (const auto& [id, ft] : c) d += std::memcmp(&a.at(id), &ft, sizeof ft) != 0;
    return d;
  };
  in.evaluate(p, b, req);
  const auto before = by_id();
  EXPECT_GT(in.stats().contacts_pb, p.size() / 2);  // on the floor, some also on walls
  EXPECT_EQ(in.stats().contacts_pp, 0u);

  std::vector<std::int64_t> ids_before(p.id.begin(), p.id.end());
  in.force_rebuild(p, b, true);
  EXPECT_NE(ids_before, p.id);  // the rebuild did reorder
  in.evaluate(p, b, req);
  EXPECT_EQ(equal(before, by_id()), 0u);

  std::vector<char> keep(p.size(), 1);
  for (std::size_t i = 0; i < p.size(); ++i) keep[i] = p.id[i] % 5 != 2;
  in.remove_particles(p, b, keep);
  in.evaluate(p, b, req);
  EXPECT_LT(p.size(), ids_before.size());
  EXPECT_EQ(equal(before, by_id()), 0u);

  // The same state without any history gives other forces: the test sees the history.
  Scene bare = fresh_scene;
  bare.particles = p;
  resolve_material_variants(bare.model, bare.particles, bare.barriers, "");
  Interactions fresh(bare.model, bare.particles, bare.barriers, integrator_policy(bare.model.params));
  fresh.evaluate(bare.particles, bare.barriers, req);
  std::size_t differ = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    differ += std::memcmp(&bare.particles.force[i], &p.force[i], sizeof(Vec3)) != 0;
  EXPECT_GT(differ, p.size() / 2);
}
