// Parallel bonds (contact/bonds.hpp) across a periodic boundary and to clumps' members:
// - the cantilever chain of test_bonds.cpp laid across the periodic face of the domain deflects
//   as the plain chain does (its discrete closed form, 1e-3; the bonds see the minimum image);
// - a two-sphere clump hanging by a bond from a fixed sphere stretches the bond by
//   M g L / (E A) (1e-3), M the clump's mass: the bond's force on the member reaches the body;
//   members of one body are never bonded to each other.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "contact/bonds.hpp"
#include "sim/simulation.hpp"
#include "support/bonded_scenes.hpp"
#include "support/clump_scenes.hpp"

using namespace mpdem;
using namespace mpdem::test;

namespace {
constexpr double kL = 2.0 * kBondR;  // m
constexpr double kKappa = 2.5;
double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }
const char* name(Integrator i) { return i == Integrator::Verlet ? "verlet" : "trapezoidal"; }
}  // namespace

TEST(BondsPeriodic, CantileverAcrossThePeriodicFace) {
  constexpr int kN = 10;
  constexpr double kF = 1e-3, kPeriod = 40e-3;  // N, m
  const double closed = chain_tip_deflection(kN, kF, kKappa);
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const double dt = 2e-7;
    Scene s = bonded_scene(dt, integ, 0.7, 0.04);
    DomainParams& d = s.model.params.domain;
    d.bounded = true;
    d.min = {0.0, -0.01, -0.01};
    d.max = {kPeriod, 0.01, 0.01};
    d.periodic = {true, false, false};
    // Sphere k at 30 + 2k mm, wrapped: spheres 5..10 sit at 0..10 mm, across the face at 40 mm.
    for (int k = 0; k <= kN; ++k) add_particle(s, k + 1, kBondR, {std::fmod(30e-3 + kL * k, kPeriod), 0.0, 0.0});
    s.particles.fixed[0] = 1;
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    ASSERT_EQ(sim.interactions().bonds()->size(), static_cast<std::size_t>(kN));
    for (const BondRecord& r : sim.interactions().bonds()->records()) EXPECT_NEAR(r.length, kL, 1e-15);
    sim.interactions().external_loads().set({kN + 1}, {{0.0, kF, 0.0}}, {Vec3{}});
    for (int k = 0; k < 60000; ++k) sim.advance(dt);
    const Particles& p = sim.particles();
    const double y = p.x[index_of(p, kN + 1)].y;
    std::printf("%s: tip deflection across the face %.6e m, discrete chain %.6e m, rel %.2e\n", name(integ), y, closed,
                rel(y, closed));
    EXPECT_LT(rel(y, closed), 1e-3);
  }
}

TEST(BondsClumps, HangingClumpStretchesMgLOverEA) {
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const double dt = 2e-7, g = 9.81;
    Scene s = bonded_scene(dt, integ, 0.7, 0.04);
    s.model.params.fields.gravity = {0.0, 0.0, -g};
    add_particle(s, 1, kBondR, {0.0, 0.0, 0.0});
    s.particles.fixed[0] = 1;
    // Two members 1.5 R apart (they overlap: one body), the top one a bond's length below.
    const int t = add_template(s, "pair", {{{0.0, 0.0, 0.75 * kBondR}, kBondR}, {{0.0, 0.0, -0.75 * kBondR}, kBondR}});
    add_clump(s, 10, t, {0.0, 0.0, -kL - 0.75 * kBondR});
    finish_clumps(s);
    const double mass = s.particles.bodies.mass[0];
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    // One bond: sphere 1 to the top member; none between the members (overlapping, same body).
    ASSERT_EQ(sim.interactions().bonds()->size(), 1u);
    for (int k = 0; k < 40000; ++k) sim.advance(dt);
    const Particles& p = sim.particles();
    const double stretch = -p.bodies.x[0].z - 0.75 * kBondR - kL, closed = mass * g * kL / (kBondE * kBondArea);
    std::printf("%s: clump hangs with a stretch %.6e m, M g L / (E A) %.6e m, rel %.2e\n", name(integ), stretch, closed,
                rel(stretch, closed));
    EXPECT_LT(rel(stretch, closed), 1e-3);
  }
}
