// The parallel bond's closed forms (physics/parallel_bond.hpp, docs/physics.md section 22):
// section, springs, rim stresses and energy against their definitions, and the critical step
// against a bonded pair integrated by velocity Verlet just below and just above it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/run_error.hpp"
#include "physics/parallel_bond.hpp"
#include "sim/simulation.hpp"
#include "support/bonded_scenes.hpp"

using namespace mpdem;

TEST(ParallelBond, SectionSpringsStressesEnergy) {
  const double r = 0.7e-3, L = 1.9e-3, E = 2e9, kappa = 2.0;
  const BondSection s = bond_section(r);
  EXPECT_DOUBLE_EQ(s.area, std::numbers::pi * r * r);
  EXPECT_DOUBLE_EQ(s.inertia, std::numbers::pi * std::pow(r, 4) / 4.0);
  EXPECT_DOUBLE_EQ(s.polar, 2.0 * s.inertia);
  const BondSprings k = bond_springs(s, L, E, kappa);
  EXPECT_DOUBLE_EQ(k.normal, E / L * s.area);
  EXPECT_DOUBLE_EQ(k.shear, E / L / kappa * s.area);
  EXPECT_DOUBLE_EQ(k.twist, E / L / kappa * s.polar);
  EXPECT_DOUBLE_EQ(k.bend, E / L * s.inertia);
  // Tension (F_n < 0) and bending add on the rim; shear and twist likewise.
  const Vec3 ms{0.0, 3e-4, -4e-4}, fs{1.0, -2.0, 2.0};  // N m (|ms| = 5e-4), N (|fs| = 3)
  EXPECT_DOUBLE_EQ(bond_tensile_stress(s, -2.0, ms), 2.0 / s.area + 5e-4 * r / s.inertia);
  EXPECT_DOUBLE_EQ(bond_tensile_stress(s, 2.0, {}), -2.0 / s.area);  // compression: no tension
  EXPECT_DOUBLE_EQ(bond_shear_stress(s, fs, -1e-4), 3.0 / s.area + 1e-4 * r / s.polar);
  EXPECT_DOUBLE_EQ(bond_energy(k, -2.0, fs, -1e-4, ms),
                   0.5 * (4.0 / k.normal + 9.0 / k.shear + 1e-8 / k.twist + 25e-8 / k.bend));
}

namespace {
// Two free equal spheres bonded, given a relative spin and a relative transverse velocity (the
// modes that turn them), integrated by velocity Verlet at `factor` x the bond's critical step:
// the largest kinetic energy over 4000 steps relative to the start (infinite if it diverged).
double growth(double factor) {
  using namespace mpdem::test;
  const double m = kBondRho * 4.0 / 3.0 * std::numbers::pi * std::pow(kBondR, 3);
  const BondSprings k = bond_springs(bond_section(kBondR), 2.0 * kBondR, kBondE, 2.5);
  const double dt = factor * bond_critical_step(k, 0.5 * m, 0.5 * 0.4 * m * kBondR * kBondR, kBondR);
  Scene s = bonded_scene(dt, Integrator::Verlet, 0.0, 0.0);
  s.model.params.checks.energy_jump = 0.0;
  s.model.params.checks.max_overlap = 0.0;
  add_particle(s, 1, kBondR, {0.0, 0.0, 0.0}, {0.0, 0.01, 0.0}, {0.0, 0.0, 10.0});
  add_particle(s, 2, kBondR, {2.0 * kBondR, 0.0, 0.0}, {0.0, -0.01, 0.0}, {0.0, 0.0, -10.0});
  s.particles.v[0].x = 0.01;  // and the normal mode
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  const auto energy = [&] {
    const Particles& p = sim.particles();
    double e = 0.0;
    for (std::size_t i = 0; i < 2; ++i)
      e += 0.5 * p.mass[i] * dot(p.v[i], p.v[i]) + 0.5 * p.inertia[i] * dot(p.w[i], p.w[i]);
    return e;
  };
  const double e0 = energy();
  double worst = 0.0;
  try {
    for (int n = 0; n < 4000; ++n) {
      sim.advance(dt);
      worst = std::max(worst, energy() / e0);
      if (!(worst < 1e6)) return INFINITY;
    }
  } catch (const RunError&) {
    return INFINITY;  // the health scan stopped a diverged state
  }
  return worst;
}
}  // namespace

TEST(ParallelBond, CriticalStepBoundsVerletsStability) {
  const double below = growth(0.9), above = growth(1.2);
  std::printf("largest kinetic energy / start: %.3g at 0.9 x the critical step, %.3g at 1.2 x\n", below, above);
  EXPECT_LT(below, 10.0);
  EXPECT_GT(above, 1e6);
}
