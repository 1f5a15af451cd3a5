// Parallel bonds through the engine (contact/bonds.hpp), elastic, against closed forms
// (docs/physics.md "Parallel bonds", docs/validation.md "Bonds"); spheres r = 1 mm, 2500 kg/m^3,
// lambda = 1, E_b = 1 GPa, k_n/k_s = 2.5, damped to rest by the bonds' dashpots and a drag:
// - a chain of 11 touching spheres (L = 20 mm), the first fixed, a 1 mN tip load across it:
//   the tip deflects by the chain's discrete closed form (1e-3) and by Euler-Bernoulli's
//   F L^3 / (3 E I) = 3.395 um (3 %);
// - the same chain pulled along its axis stretches F L / (E A) (1e-3), twisted by a torque T
//   turns T L / (G J) (1e-3) with G = E / (k_n/k_s);
// - a pair hanging under gravity from a fixed sphere stretches m g L / (E A) (1e-3);
// in both integrators.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

#include "contact/bonds.hpp"
#include "sim/simulation.hpp"
#include "support/bonded_scenes.hpp"

using namespace mpdem;
using namespace mpdem::test;

namespace {

constexpr int kN = 10;               // bonds of the chain
constexpr double kL = 2.0 * kBondR;  // m, bond length
constexpr double kKappa = 2.5;       // k_n / k_s
constexpr double kF = 1e-3;          // N
double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }
const char* name(Integrator i) { return i == Integrator::Verlet ? "verlet" : "trapezoidal"; }

double chain_deflection(double f) { return chain_tip_deflection(kN, f, kKappa); }

// Runs the scene `s` with the external load (force f, torque t) on the last particle until rest.
std::unique_ptr<Simulation> settle(Scene s, const Vec3& f, const Vec3& t, double dt, int steps) {
  auto sim = std::make_unique<Simulation>(std::move(s), RunOptions{{}, false, false});
  sim->interactions().external_loads().set({kN + 1}, {f}, {t});
  for (int k = 0; k < steps; ++k) sim->advance(dt);
  return sim;
}

}  // namespace

TEST(BondClosedForm, IssueNumbers) {
  const double eb = kF * std::pow(kN * kL, 3) / (3.0 * kBondE * kBondI);
  EXPECT_NEAR(eb, 3.395e-6, 0.001e-6);
  // The discrete chain lies 0.25 % below Euler-Bernoulli's bending and adds its shear.
  EXPECT_LT(rel(chain_deflection(kF), eb), 0.03);
}

// The made bonds: 10 along the chain, of the spheres' distance and radius.
TEST(Bonds, MadeByTheGapRule) {
  Scene s = bonded_scene(1e-7, Integrator::Verlet, 0.0, 0.0);
  add_chain(s, kN + 1);
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  const Bonds* b = sim.interactions().bonds();
  ASSERT_NE(b, nullptr);
  ASSERT_EQ(b->size(), static_cast<std::size_t>(kN));
  for (std::size_t k = 0; k < b->size(); ++k) {
    EXPECT_EQ(b->records()[k].id_i, static_cast<std::int64_t>(k + 1));
    EXPECT_EQ(b->records()[k].id_j, static_cast<std::int64_t>(k + 2));
    EXPECT_NEAR(b->records()[k].length, kL, 1e-15);
    EXPECT_EQ(b->records()[k].radius, kBondR);
  }
}

TEST(Bonds, CantileverAgainstEulerBernoulliAndTheDiscreteChain) {
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const double dt = 2e-7;
    Scene s = bonded_scene(dt, integ, 0.7, 0.04);
    add_chain(s, kN + 1);
    const auto sim = settle(std::move(s), {0.0, kF, 0.0}, {}, dt, 60000);
    const Particles& p = sim->particles();
    const double y = p.x[index_of(p, kN + 1)].y, eb = kF * std::pow(kN * kL, 3) / (3.0 * kBondE * kBondI);
    std::printf("%s: tip deflection %.6e m, discrete chain %.6e m (rel %.2e), Euler-Bernoulli %.6e m (rel %.2e)\n",
                name(integ), y, chain_deflection(kF), rel(y, chain_deflection(kF)), eb, rel(y, eb));
    EXPECT_LT(rel(y, chain_deflection(kF)), 1e-3);
    EXPECT_LT(rel(y, eb), 0.03);
    EXPECT_LT(norm(p.v[index_of(p, kN + 1)]), 1e-6);  // at rest
  }
}

TEST(Bonds, ChainStretchesFLOverEA) {
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const double dt = 2e-7;
    Scene s = bonded_scene(dt, integ, 0.7, 0.04);
    add_chain(s, kN + 1);
    const auto sim = settle(std::move(s), {kF, 0.0, 0.0}, {}, dt, 30000);
    const Particles& p = sim->particles();
    const double stretch = p.x[index_of(p, kN + 1)].x - kN * kL, closed = kF * kN * kL / (kBondE * kBondArea);
    std::printf("%s: stretch %.6e m, F L / (E A) %.6e m, rel %.2e\n", name(integ), stretch, closed,
                rel(stretch, closed));
    EXPECT_LT(rel(stretch, closed), 1e-3);
  }
}

TEST(Bonds, ChainTwistsTLOverGJ) {
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const double dt = 2e-7, torque = 1e-6;  // N m
    Scene s = bonded_scene(dt, integ, 0.7, 0.04);
    add_chain(s, kN + 1);
    const auto sim = settle(std::move(s), {}, {torque, 0.0, 0.0}, dt, 30000);
    const Particles& p = sim->particles();
    const Quat& q = p.q[index_of(p, kN + 1)];
    const double turn = 2.0 * std::atan2(q.x, q.w);  // rad, about x
    const double closed = torque * kN * kL / ((kBondE / kKappa) * kBondJ);
    std::printf("%s: twist %.6e rad, T L / (G J) %.6e rad, rel %.2e\n", name(integ), turn, closed, rel(turn, closed));
    EXPECT_LT(rel(turn, closed), 1e-3);
  }
}

TEST(Bonds, HangingPairStretchesMgLOverEA) {
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const double dt = 2e-7, g = 9.81;
    Scene s = bonded_scene(dt, integ, 0.7, 0.04);
    s.model.params.fields.gravity = {0.0, 0.0, -g};
    add_particle(s, 1, kBondR, {0.0, 0.0, 0.0});
    add_particle(s, 2, kBondR, {0.0, 0.0, -kL});
    s.particles.fixed[0] = 1;
    const double m = s.particles.mass[1];
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    for (int k = 0; k < 30000; ++k) sim.advance(dt);
    const Particles& p = sim.particles();
    const double stretch = -p.x[index_of(p, 2)].z - kL, closed = m * g * kL / (kBondE * kBondArea);
    std::printf("%s: stretch %.6e m, m g L / (E A) %.6e m, rel %.2e\n", name(integ), stretch, closed,
                rel(stretch, closed));
    EXPECT_LT(rel(stretch, closed), 1e-3);
    EXPECT_EQ(sim.interactions().stats().bonds_intact, 1u);
  }
}

// A pair of a material variant (per-row CSV values make one, model/material_variants.hpp) takes
// its base material's [[bonds.pair]] entry, in the bonds' force as in their making: a pair
// entry a-a with E_b = 2 GPa stretches the hanging pair by m g L / (2 GPa A).
TEST(Bonds, MaterialVariantTakesItsBasesPairEntry) {
  const double dt = 2e-7, g = 9.81, young = 2e9;
  Scene s = bonded_scene(dt, Integrator::Verlet, 0.7, 0.04);
  s.model.params.fields.gravity = {0.0, 0.0, -g};
  Material variant = s.model.materials.front();
  variant.name = s.model.materials.front().name + "#1";
  variant.variant_of = 0;
  s.model.materials.push_back(variant);
  BondPairParams pair;
  pair.material_a = pair.material_b = s.model.materials.front().name;
  pair.keys.young = young;
  s.model.params.bonds.pairs.push_back(pair);
  add_particle(s, 1, kBondR, {0.0, 0.0, 0.0});
  add_particle(s, 2, kBondR, {0.0, 0.0, -kL});
  s.particles.fixed[0] = 1;
  s.particles.material[0] = s.particles.material[1] = 1;  // the variant
  const double m = s.particles.mass[1];
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  ASSERT_EQ(sim.interactions().bonds()->size(), 1u);
  for (int k = 0; k < 30000; ++k) sim.advance(dt);
  const Particles& p = sim.particles();
  const double stretch = -p.x[index_of(p, 2)].z - kL, closed = m * g * kL / (young * kBondArea);
  std::printf("variant: stretch %.6e m, m g L / (E A) %.6e m, rel %.2e\n", stretch, closed, rel(stretch, closed));
  EXPECT_LT(rel(stretch, closed), 1e-3);
}
