// Rigid barriers ([[barriers]] rigid = true: elements with E = +inf, physics.md section 7): the
// particle's moduli alone set the contact, E* = E/(1 - nu^2), G* = G/(2 - nu). Checked on the
// resolved contact table and on a sphere impact through the whole engine against the Hertz
// closed forms.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "contact/contact_table.hpp"
#include "model/material_variants.hpp"
#include "sim/simulation.hpp"
#include "support/barrier_mechanics_scene.hpp"
#include "support/contact_scenes.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;
using namespace mpdem::test;  // kR, kNu, kPi, name, base_scene

namespace {

double rel(double a, double b) { return std::abs(a / b - 1.0); }

// A steel-like sphere, so that a steel barrier halves E* against a rigid one (a measurable
// difference; the suite's soft 1e7 Pa beads would see a steel barrier as practically rigid).
constexpr double kSteelE = 2.1e11;    // Pa
constexpr double kSteelRho = 7850.0;  // kg/m^3

// (a) The particle-barrier law the kernels use, resolved for barrier elements with E = +inf via
// the material variants, equals the rigid limits; no entry of the table is NaN.
TEST(RigidBarrier, ResolvedLawHasTheParticlesModuliAlone) {
  for (const double nu : {0.0, 0.3, 0.49}) {
    Scene s = make_scene(1e-6, 1.0);
    set_material(s, kSteelRho, kSteelE, nu);
    s.model.materials.front().name = "steel";
    add_particle(s, 1, kR, {0.0, 0.0, 1.0});
    add_flat_square(s.barriers, "rigid", {}, 0.1, 1, kRigidYoung, 0.2);
    add_flat_square(s.barriers, "steel", {0.0, 0.0, -1.0}, 0.1, 1, kSteelE, nu);
    std::fill(s.barriers.material.begin(), s.barriers.material.end(), 0);  // the source's material: steel
    resolve_material_variants(s.model, s.particles, s.barriers, "");
    ContactTable t;
    t.build(s.model);
    const auto pm = static_cast<std::size_t>(s.particles.material[0]);
    const auto rigid = static_cast<std::size_t>(s.barriers.material.front());
    const auto steel = static_cast<std::size_t>(s.barriers.material.back());
    ASSERT_TRUE(is_rigid(s.model.materials[rigid]));
    ASSERT_EQ(s.model.materials[rigid].variant_of, 0);  // a variant of the source's material
    const double G = kSteelE / (2.0 * (1.0 + nu));
    const PairLaw& l = t.barrier_pair(pm, rigid);
    std::printf("nu %.2f: cn rel err %.1e, ct rel err %.1e\n", nu,
                rel(l.c[HertzLaw::kTwiceE], 2.0 * kSteelE / (1.0 - nu * nu)),
                rel(l.c[HertzLaw::kEightG], 8.0 * G / (2.0 - nu)));
    EXPECT_LT(rel(l.c[HertzLaw::kTwiceE], 2.0 * kSteelE / (1.0 - nu * nu)), 1e-14);
    EXPECT_LT(rel(l.c[HertzLaw::kEightG], 8.0 * G / (2.0 - nu)), 1e-14);
    // Same material on both sides: twice the compliance, half the moduli.
    EXPECT_LT(rel(t.barrier_pair(pm, steel).c[HertzLaw::kTwiceE], kSteelE / (1.0 - nu * nu)), 1e-14);
    EXPECT_LT(rel(t.barrier_pair(pm, steel).c[HertzLaw::kEightG], 4.0 * G / (2.0 - nu)), 1e-14);
    for (std::size_t a = 0; a < t.materials(); ++a)
      for (std::size_t b = 0; b < t.materials(); ++b)
        for (const PairLaw* q : {&t.particle_pair(a, b), &t.barrier_pair(a, b)})
          EXPECT_TRUE(std::isfinite(q->c[HertzLaw::kTwiceE]) && std::isfinite(q->c[HertzLaw::kEightG]) &&
                      std::isfinite(q->shear_root()))
              << a << " " << b;
  }
}

struct Impact {
  double delta_max = 0.0, t_c = 0.0;  // m, s
  double e = 0.0;                     // -, rebound speed / impact speed
};

// Steel sphere thrown with speed v (no gravity) onto an 8 x 8-cell flat square in z = 0 of
// modulus Eb (kRigidYoung: rigid), away from seams; dt = t_c / 1000 of the expected impact.
Impact impact(Integrator integ, double v, double Eb, double e, double Es_expected) {
  const double m = 4.0 / 3.0 * kPi * kR * kR * kR * kSteelRho;
  const double dmax = std::pow(15.0 * m * v * v / (16.0 * Es_expected * std::sqrt(kR)), 0.4);
  const double dt = 2.943275 * dmax / v / 1000.0;
  Scene s = base_scene(integ, dt, {});
  set_material(s, kSteelRho, kSteelE, kNu);
  add_flat_square(s.barriers, "floor", {}, 0.1, 8, Eb, kNu);
  if (e < 1.0) s.model.params.contact.particle_barrier.restitution = e;
  else s.model.params.contact.particle_barrier.damping_ratio = 0.0;
  const double gap = 3.3 * v * dt;
  add_particle(s, 1, kR, {0.0031, -0.0042, kR + gap}, {0.0, 0.0, -v});
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  const Particles& p = sim.particles();
  Impact r;
  double ov_prev = -gap, t_start = -1.0;
  for (int k = 0; k < 20000; ++k) {
    sim.advance(dt);
    const double ov = kR - p.x[0].z, t = sim.time();
    r.delta_max = std::max(r.delta_max, ov);
    if (ov_prev <= 0.0 && ov > 0.0 && t_start < 0.0) t_start = t - dt * ov / (ov - ov_prev);
    if (ov_prev > 0.0 && ov <= 0.0) {
      r.t_c = (t - dt * (-ov) / (ov_prev - ov)) - t_start;
      r.e = p.v[0].z / v;
      break;
    }
    ov_prev = ov;
  }
  return r;
}

// (b) Elastic impact on a rigid floor: maximum overlap within 0.5 % and contact time within 1 %
// of the Hertz closed forms with E* = E/(1 - nu^2), r* = R, m* = m (the tolerances of
// test_sphere_on_barrier.cpp); a steel floor (E* of (51), half as large) gives an overlap
// 2^0.4 = 1.32 times and a contact time as much longer, matched to 1 %. A damped impact on the
// rigid floor keeps the requested restitution (within 0.005, as RestitutionSweep).
TEST(RigidBarrier, ImpactMatchesHertzWithTheParticlesModulus) {
  const double m = 4.0 / 3.0 * kPi * kR * kR * kR * kSteelRho;
  const double Es_rigid = kSteelE / (1.0 - kNu * kNu), Es_steel = 0.5 * Es_rigid;
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal})
    for (const double v : {0.1, 1.0}) {
      const Impact rigid = impact(integ, v, kRigidYoung, 1.0, Es_rigid);
      const Impact steel = impact(integ, v, kSteelE, 1.0, Es_steel);
      const double dmax = std::pow(15.0 * m * v * v / (16.0 * Es_rigid * std::sqrt(kR)), 0.4);
      const double tc = 2.943275 * dmax / v;
      std::printf("[%s v=%g] rigid: delta_max err %.2e, t_c err %.2e, e %.6f; steel/rigid: delta %.5f, t_c %.5f "
                  "(expected %.5f)\n",
                  name(integ), v, rigid.delta_max / dmax - 1.0, rigid.t_c / tc - 1.0, rigid.e,
                  steel.delta_max / rigid.delta_max, steel.t_c / rigid.t_c, std::pow(2.0, 0.4));
      EXPECT_NEAR(rigid.delta_max / dmax, 1.0, 0.005);
      EXPECT_NEAR(rigid.t_c / tc, 1.0, 0.01);
      EXPECT_NEAR(rigid.e, 1.0, 1e-4);
      EXPECT_NEAR(steel.delta_max / rigid.delta_max, std::pow(2.0, 0.4), 0.01);
      EXPECT_NEAR(steel.t_c / rigid.t_c, std::pow(2.0, 0.4), 0.01);
      const Impact damped = impact(integ, v, kRigidYoung, 0.5, Es_rigid);
      std::printf("[%s v=%g] rigid, e = 0.5: achieved %.5f\n", name(integ), v, damped.e);
      EXPECT_NEAR(damped.e, 0.5, 0.005);
    }
}

}  // namespace
