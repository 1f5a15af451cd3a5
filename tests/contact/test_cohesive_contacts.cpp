// Contacts with cohesion through the engine (contact/cohesive_contact.hpp): JKR's neck
// (contact/laws/jkr.hpp) held past touching until delta_c and its state kept per contact,
// against the closed forms of Johnson, Kendall & Roberts (1971) for two equal spheres
// (E = 1e7 Pa, nu = 0.3, R = 1 mm: E* = 5.495 MPa, r* = 0.5 mm; w = 0.05 J/m^2):
// - at rest without load (damped, no gravity) the overlap settles at delta_0 = 0.674 um (1e-3);
// - pulled apart by a slowly rising force they part at F_c = 3/2 pi w r* = 117.8 uN (1 %);
// - pulled apart at a slow prescribed speed the neck breaks at delta_c = -0.557 um, the force
//   then -5/9 F_c = -65.4 uN (1 %);
// - a loading-unloading cycle at a prescribed speed dissipates the energy of the neck at the
//   break, U(delta_c) (2 %), which the energy balance books as cohesion_dissipated;
// and the invariances: both integrators, thread count, bitwise resume through a break.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "sim/simulation.hpp"
#include "support/contact_scenes.hpp"
#include "support/scene_builder.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kE = 1e7, kNu = 0.3, kR = 1e-3, kW = 0.05, kRho = 2500.0;
const double kEStar = kE / (2.0 * (1.0 - kNu * kNu));  // Pa, (51) for two equal materials
constexpr double kRStar = 0.5 * kR;                    // m
double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

// The closed forms, written out here independently of the law's header.
// a(delta) is parametric: delta(a) = a^2/r* - sqrt(2 pi w a / E*), F(a) = 4 E* a^3/(3 r*) - sqrt(8 pi w E* a^3).
double jkr_delta(double a) { return a * a / kRStar - std::sqrt(2.0 * kPi * kW * a / kEStar); }
double jkr_force(double a) {
  return 4.0 * kEStar * a * a * a / (3.0 * kRStar) - std::sqrt(8.0 * kPi * kW * kEStar * a * a * a);
}
const double kA0 = std::cbrt(9.0 * kPi * kW * kRStar * kRStar / (2.0 * kEStar));             // m, zero load
const double kDelta0 = jkr_delta(kA0);                                                       // m
const double kFc = 1.5 * kPi * kW * kRStar;                                                  // N
const double kDeltaC = -0.75 * std::cbrt(kPi * kPi * kW * kW * kRStar / (kEStar * kEStar));  // m
// The contact radius at delta_c, where d delta / da = 0: a_c = (pi w r*^2 / (8 E*))^(1/3).
const double kAc = std::cbrt(kPi * kW * kRStar * kRStar / (8.0 * kEStar));
// J, U(delta_c) = -integral of F over [delta_c, 0] along the branch: Simpson in a (smooth there).
double neck_energy() {
  const double a1 = std::cbrt(2.0 * kPi * kW * kRStar * kRStar / kEStar);  // m, the contact radius at delta = 0
  const int n = 20000;
  const auto integrand = [](double a) {
    const double dd = 2.0 * a / kRStar - 0.5 * std::sqrt(2.0 * kPi * kW / (kEStar * a));  // d delta / da
    return jkr_force(a) * dd;
  };
  double sum = 0.0;
  const double h = (a1 - kAc) / n;
  for (int k = 0; k <= n; ++k) sum += (k == 0 || k == n ? 1.0 : (k % 2 ? 4.0 : 2.0)) * integrand(kAc + k * h);
  return -sum * h / 3.0;  // -integral_{delta_c}^{0} F d delta  (> 0: F < 0 there)
}

Scene jkr_scene(double dt, Integrator integ, double restitution = 0.3) {
  Scene s = test::make_scene(dt, 10.0);
  s.model.params.time.integrator = integ;
  s.model.params.fields.gravity = {};
  s.model.params.checks.max_overlap = 0.0;
  test::set_material(s, kRho, kE, kNu);
  for (ContactLawParams* c : {&s.model.params.contact.particle_particle, &s.model.params.contact.particle_barrier}) {
    c->cohesion = "jkr";
    c->law_keys["surface_energy"] = kW;
    if (restitution < 1.0) c->restitution = restitution;
    else c->damping_ratio = 0.0;
  }
  return s;
}

double pair_overlap(const Particles& p) {
  return 2.0 * kR - norm(p.x[test::index_of(p, 2)] - p.x[test::index_of(p, 1)]);
}

}  // namespace

// The closed forms the tests use reproduce the issue's numbers.
TEST(JkrClosedForm, IssueNumbers) {
  EXPECT_NEAR(kEStar, 5.495e6, 1e3);
  EXPECT_NEAR(kA0, 31.80e-6, 0.01e-6);
  EXPECT_NEAR(kDelta0, 0.674e-6, 0.001e-6);
  EXPECT_NEAR(kFc, 117.8e-6, 0.1e-6);
  EXPECT_NEAR(kDeltaC, -0.557e-6, 0.001e-6);
  EXPECT_LT(rel(jkr_delta(kAc), kDeltaC), 1e-12);
  EXPECT_LT(rel(jkr_force(kAc), -5.0 / 9.0 * kFc), 1e-12);
  EXPECT_NEAR(jkr_force(kAc), -65.4e-6, 0.1e-6);
  EXPECT_LT(std::abs(jkr_force(kA0)), 1e-12 * kFc);
}

// Two spheres just touching, no gravity, damped: the neck pulls them to the zero-load overlap,
// in both integrators.
TEST(JkrContact, SettlesAtTheZeroLoadOverlap) {
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const double dt = 1e-6;
    Scene s = jkr_scene(dt, integ);
    test::add_particle(s, 1, kR, {-kR + 0.05e-6, 0.0, 0.0});
    test::add_particle(s, 2, kR, {kR - 0.05e-6, 0.0, 0.0});
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    for (int k = 0; k < 30000; ++k) sim.advance(dt);
    const double d = pair_overlap(sim.particles());
    std::printf("%s: rest overlap %.6e m, closed form %.6e m, relative %.2e\n",
                integ == Integrator::Verlet ? "verlet" : "trapezoidal", d, kDelta0, rel(d, kDelta0));
    EXPECT_LT(rel(d, kDelta0), 1e-3);
    EXPECT_EQ(sim.interactions().stats().contacts_pp, 1u);
  }
}

// A force rising slowly pulls the spheres apart: they part at the pull-off F_c (force control:
// past the minimum of F the neck runs to delta_c at once).
TEST(JkrContact, PullOffUnderARisingForce) {
  const double dt = 1e-6, rate = 2e-4;  // N/s: F_c after ~590000 steps
  Scene s = jkr_scene(dt, Integrator::Verlet);
  test::add_particle(s, 1, kR, {-kR + 0.5 * kDelta0, 0.0, 0.0});
  test::add_particle(s, 2, kR, {kR - 0.5 * kDelta0, 0.0, 0.0});
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  for (int k = 0; k < 20000; ++k) sim.advance(dt);
  ASSERT_EQ(sim.interactions().stats().contacts_pp, 1u);
  double parted = 0.0;
  for (int k = 0; k < 1000000 && parted == 0.0; ++k) {
    const double f = rate * k * dt;  // N
    sim.interactions().external_loads().set({1, 2}, {{-f, 0.0, 0.0}, {f, 0.0, 0.0}}, {Vec3{}, Vec3{}});
    sim.advance(dt);
    if (sim.interactions().stats().contacts_pp == 0) parted = f;
  }
  std::printf("parted at %.6e N, F_c = %.6e N, relative %.2e\n", parted, kFc, rel(parted, kFc));
  EXPECT_LT(rel(parted, kFc), 1e-2);
  EXPECT_EQ(sim.interactions().stats().cohesion_breaks, 1u);
}

// Displacement control: sphere 1 held at rest, sphere 2 held moving away at 10 um/s (both
// fixed: their forces are the contact's alone). The neck holds past touching and breaks at
// delta_c, the force on the fixed sphere there -5/9 F_c; nothing after.
TEST(JkrContact, BreaksAtTheCriticalOverlapUnderDisplacementControl) {
  const double dt = 1e-6, v = 1e-5;
  Scene s = jkr_scene(dt, Integrator::Verlet, 1.0);
  const std::size_t i1 = test::add_particle(s, 1, kR, {-kR + 0.5 * kDelta0, 0.0, 0.0});
  const std::size_t i2 = test::add_particle(s, 2, kR, {kR - 0.5 * kDelta0, 0.0, 0.0}, {v, 0.0, 0.0});
  s.particles.fixed[i1] = s.particles.fixed[i2] = 1;
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  const Particles& p = sim.particles();
  double last_overlap = 0.0, last_force = 0.0;
  bool broke = false;
  for (int k = 0; k < 300000 && !broke; ++k) {
    sim.advance(dt);
    if (sim.interactions().stats().contacts_pp == 1) {
      last_overlap = pair_overlap(p);
      last_force = p.force[test::index_of(p, 2)].x;  // > 0: pushing 2 away; < 0: the neck pulls it back
    } else {
      broke = true;
      EXPECT_EQ(p.force[test::index_of(p, 2)].x, 0.0);
    }
  }
  ASSERT_TRUE(broke);
  std::printf("last held at overlap %.6e m (delta_c %.6e), force %.6e N (closed form %.6e)\n", last_overlap, kDeltaC,
              last_force, jkr_force(kAc));
  EXPECT_LT(rel(last_overlap, kDeltaC), 1e-2);
  EXPECT_LT(rel(last_force, jkr_force(kAc)), 1e-2);
  EXPECT_LT(last_overlap, 0.0);  // held past touching
}

// A loading-unloading cycle at prescribed speed: approach from a gap to 2 um, back until the neck
// breaks. The work the holding force does over the cycle is what the contact dissipated: U(delta_c)
// (2 %), and the balance books it as cohesion_dissipated.
TEST(JkrContact, CycleDissipatesTheNeckEnergy) {
  const double dt = 1e-6, v = 1e-5, gap = 0.2e-6, depth = 2e-6;
  Scene s = jkr_scene(dt, Integrator::Verlet, 1.0);
  const std::size_t i1 = test::add_particle(s, 1, kR, {-kR - 0.5 * gap, 0.0, 0.0});
  const std::size_t i2 = test::add_particle(s, 2, kR, {kR + 0.5 * gap, 0.0, 0.0}, {-v, 0.0, 0.0});
  s.particles.fixed[i1] = s.particles.fixed[i2] = 1;
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  Particles& p = sim.particles();
  const std::size_t j = test::index_of(p, 2);
  double work = 0.0;  // J, by what holds sphere 2: -F . v dt (trapezoid)
  double f_prev = 0.0;
  bool reversed = false;
  for (int k = 0; k < 2000000; ++k) {
    const double vx = p.v[j].x;
    sim.advance(dt);
    const double f = p.force[j].x;
    work += -0.5 * (f_prev + f) * vx * dt;
    f_prev = f;
    if (!reversed && pair_overlap(p) >= depth) {
      p.v[j].x = v;
      reversed = true;
    }
    if (reversed && pair_overlap(p) < kDeltaC - 1e-8) break;
  }
  ASSERT_TRUE(reversed);
  const double expected = neck_energy();
  const InteractionStats& st = sim.interactions().stats();
  std::printf("cycle work %.6e J, booked %.6e J, closed form U(delta_c) %.6e J\n", work, st.cohesion_dissipated,
              expected);
  EXPECT_LT(rel(work, expected), 2e-2);
  EXPECT_LT(rel(st.cohesion_dissipated, expected), 2e-2);
  EXPECT_EQ(st.cohesion_breaks, 1u);
}

namespace {

// Willett et al. (2000), Langmuir 16, 9396, as in Yade's capillary example: equal spheres
// R = 2.381 mm, gamma = 20.6 mN/m, theta = 0, V = 74.2 nL (no viscous term).
constexpr double kWillettR = 2.381e-3, kGamma = 20.6e-3, kVolume = 74.2e-12;
double willett_force(double gap) {  // N, the equal-sphere closed form, attractive
  const double s = 0.5 * gap * std::sqrt(kWillettR / kVolume);
  return 2.0 * kPi * kWillettR * kGamma / (1.0 + 2.1 * s + 10.0 * s * s);
}

Scene bridge_scene(double dt, Integrator integ) {
  Scene s = test::make_scene(dt, 10.0);
  s.model.params.time.integrator = integ;
  s.model.params.fields.gravity = {};
  s.model.params.checks.max_overlap = 0.0;
  test::set_material(s, kRho, kE, kNu);
  LiquidBridgeKeys k;
  k.model = "willett";
  k.surface_tension = kGamma;
  k.contact_angle = 0.0;
  k.volume = kVolume;
  s.model.params.contact.liquid_bridge.defaults = k;
  return s;
}

}  // namespace

// Two fixed spheres touching at t = 0 (the bridge forms), sphere 2 held moving away at 1 mm/s:
// the force on each (the particles' force array, fixed ones included) is Willett's at the gap
// (1e-3), and nothing once the gap passes the rupture distance V^(1/3) = 0.420 mm.
TEST(LiquidBridge, WillettForceAgainstTheGapAndRupture) {
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const double dt = 2e-6, v = 1e-3;
    Scene s = bridge_scene(dt, integ);
    const std::size_t i1 = test::add_particle(s, 1, kWillettR, {-kWillettR, 0.0, 0.0});
    const std::size_t i2 = test::add_particle(s, 2, kWillettR, {kWillettR + 1e-12, 0.0, 0.0}, {v, 0.0, 0.0});
    s.particles.x[i2].x = kWillettR - 1e-9;  // touching: the bridge forms at the first evaluation
    s.particles.fixed[i1] = s.particles.fixed[i2] = 1;
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    const Particles& p = sim.particles();
    const auto gap = [&] { return norm(p.x[test::index_of(p, 2)] - p.x[test::index_of(p, 1)]) - 2.0 * kWillettR; };
    const double rupture = std::cbrt(kVolume);
    // m and N: Willett's table, the gaps and the printed forces of the issue.
    const double table[5][2] = {
        {0.0, 0.3082e-3}, {0.05e-3, 0.2057e-3}, {0.1e-3, 0.1286e-3}, {0.2e-3, 0.0571e-3}, {0.3e-3, 0.0308e-3}};
    std::size_t checked = 0;
    bool ruptured = false;
    for (int k = 0; k < 600000; ++k) {
      sim.advance(dt);
      const double S = gap();
      const double f1 = p.force[test::index_of(p, 1)].x, f2 = p.force[test::index_of(p, 2)].x;
      if (S < rupture) {
        ASSERT_EQ(sim.interactions().stats().bridges, 1u) << S;
        EXPECT_EQ(f1, -f2);
        if (checked < 5 && S >= table[checked][0]) {
          // The force on 1 points towards 2 (+x): attraction. Within v dt of the table's gap.
          EXPECT_LT(rel(f1, willett_force(std::max(S, 0.0))), 1e-3) << "gap " << S;
          EXPECT_LT(rel(f1, table[checked][1]), 2e-3) << "gap " << S;
          std::printf("gap %.6f mm: %.4f mN (closed form %.4f mN, Willett's table %.4f mN)\n", S * 1e3, f1 * 1e3,
                      willett_force(std::max(S, 0.0)) * 1e3, table[checked][1] * 1e3);
          ++checked;
        }
      } else if (S > rupture + 2.0 * v * dt) {
        EXPECT_EQ(f1, 0.0);
        EXPECT_EQ(sim.interactions().stats().bridges, 0u);
        ruptured = sim.interactions().stats().ruptures == 1;
        break;
      }
    }
    EXPECT_EQ(checked, 5u);
    EXPECT_TRUE(ruptured);
  }
}
