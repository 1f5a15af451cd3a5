// Near-field forces (physics.md section 4, (44)-(46)) against closed forms: the pure laws, the
// pair loop against a brute-force sum (cutoff, per-material coefficients, Newton's third law), a
// pair oscillating about the equilibrium distance of (46) (small-oscillation frequency, energy with
// the analytic potential), and two like charges flying apart (speed from the Coulomb energy).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "physics/near_field.hpp"
#include "sim/simulation.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kCoulomb = 8.9875517923e9;  // N m^2/C^2, 1/(4 pi eps0), CODATA 2018
}  // namespace

TEST(NearFieldLaws, CoulombAndEmpirical) {
  // Two 1 uC charges 1 m apart in vacuum: 8.9875517923e-3 N, repulsive; eps_r divides it.
  EXPECT_NEAR(coulomb_force(coulomb_constant(1.0), 1e-6, 1e-6, 1.0), 8.9875517923e-3, 1e-9 * 8.99e-3);
  EXPECT_NEAR(coulomb_force(coulomb_constant(4.0), 1e-6, -1e-6, 0.5), -8.9875517923e-3, 1e-9 * 8.99e-3);
  // (46) with a1 = 2, b1 = 3, a2 = 5, b2 = 2 at d = 0.5: 2 * 8 - 5 * 4 = -4 N (attractive).
  const EmpiricalLaw c{2.0, 3.0, 5.0, 2.0};
  EXPECT_DOUBLE_EQ(empirical_force(c, 0.5), -4.0);
  // The potentials are antiderivatives: -dU/dd = f (central difference, relative 1e-7),
  // including the logarithmic case b = 1.
  for (const EmpiricalLaw& law : {c, EmpiricalLaw{1e-3, 1.0, 2e-3, 4.0}, EmpiricalLaw{3.0, 12.0, 2.0, 6.0}}) {
    const double d = 0.9, h = 1e-6;
    const double dU = (empirical_potential(law, d + h) - empirical_potential(law, d - h)) / (2 * h);
    EXPECT_NEAR(-dU, empirical_force(law, d), 1e-7 * std::abs(empirical_force(law, d)) + 1e-12);
  }
  const double kc = coulomb_constant(2.0), d = 0.3, h = 1e-7;
  const double dU = (coulomb_potential(kc, 1e-6, 2e-6, d + h) - coulomb_potential(kc, 1e-6, 2e-6, d - h)) / (2 * h);
  EXPECT_NEAR(-dU, coulomb_force(kc, 1e-6, 2e-6, d), 1e-7 * coulomb_force(kc, 1e-6, 2e-6, d));
}

// Pair loop against a brute-force O(N^2) sum of the laws: a lattice of non-touching spheres of two
// materials with per-pair coefficients and charges; the cutoff (7 mm) is far beyond contact range
// plus skin, so the neighbour list must honour it. Also: total force zero (third law).
TEST(NearFieldForces, MatchesBruteForceWithCutoffAndMaterialPairs) {
  Scene s = test::make_scene(1e-6, 1e-6);
  s.model.params.fields.gravity = {};
  Material m2 = s.model.materials[0];
  m2.name = "other";
  s.model.materials.push_back(m2);
  NearFieldParams& nf = s.model.params.near_field;
  nf.coulomb = true;
  nf.permittivity = 2.5;
  nf.empirical = true;
  nf.a1 = 1e-20;
  nf.b1 = 8.0;
  nf.a2 = 2e-12;
  nf.b2 = 4.0;
  nf.pairs.push_back({"other", "default", 3e-20, 8.0, 1e-12, 3.0});
  nf.pairs.push_back({"other", "other", 0.0, 1.0, 4e-9, 2.0});
  nf.cutoff = 7e-3;
  std::int64_t id = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 3; ++k) {
        const std::size_t n = test::add_particle(s, ++id, 1e-3, {3e-3 * i + 1e-4 * (j % 3), 3e-3 * j, 3.1e-3 * k});
        s.particles.material[n] = (i + j + k) % 2;
        s.particles.charge[n] = 1e-10 * ((i * 5 + j * 3 + k) % 7 - 3);
      }
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  sim.initialize();
  const Particles& p = sim.particles();
  // The table a pair uses, written out here.
  auto coeffs = [](int a, int b) {
    if (a == 1 && b == 1) return EmpiricalLaw{0.0, 1.0, 4e-9, 2.0};
    if (a != b) return EmpiricalLaw{3e-20, 8.0, 1e-12, 3.0};
    return EmpiricalLaw{1e-20, 8.0, 2e-12, 4.0};
  };
  const double kc = kCoulomb / 2.5;
  Vec3 total{};
  double scale = 0.0, energy = 0.0;
  std::size_t in_range = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    Vec3 f{};
    for (std::size_t j = 0; j < p.size(); ++j) {
      if (j == i) continue;
      const Vec3 dx = p.x[i] - p.x[j];
      const double d = norm(dx);
      if (d >= 7e-3) continue;
      const EmpiricalLaw c = coeffs(p.material[i], p.material[j]);
      const double fs = kc * p.charge[i] * p.charge[j] / (d * d) + c.a1 * std::pow(d, -c.b1) -
                        c.a2 * std::pow(d, -c.b2);
      f += (fs / d) * dx;
      if (j > i) {
        ++in_range;
        energy += kc * p.charge[i] * p.charge[j] / d + empirical_potential(c, d);
      }
    }
    EXPECT_LT(norm(p.force[i] - f), 1e-10 * norm(f) + 1e-25) << "particle " << p.id[i];
    total += p.force[i];
    scale += norm(p.force[i]);
  }
  EXPECT_GT(in_range, 200u);  // far more pairs than touching neighbours
  EXPECT_LT(norm(total), 1e-12 * scale);
  EXPECT_NEAR(sim.interactions().stats().near_field_energy, energy, 1e-10 * std::abs(energy));
}

// ---------------------------------------------------------------------------------------------
// A pair under (46) released at rest at d0 (1 + eps): oscillates about d0 = (a1/a2)^(1/(b1-b2))
// with omega^2 = k / mu, k = a2 (b1 - b2) d0^-(b2+1), mu = m/2. Energy 1/2 m (v1^2 + v2^2) + U(d)
// with U the antiderivative of (46) written out here; its error is measured against the
// oscillation energy U(d_start) - U(d0) (much stricter than against |U|).

namespace {
struct Oscillation {
  double period_error = 0.0;  // relative
  double energy_error = 0.0;  // max relative to the oscillation energy
  int crossings = 0;
};

Oscillation oscillate(Integrator integ, int steps_per_period, double periods) {
  const double R = 1e-3, rho = 2500.0, b1 = 12.0, b2 = 6.0, d0 = 3e-3, f0 = 100.0;  // Hz
  const double m = 4.0 / 3.0 * kPi * R * R * R * rho, mu = 0.5 * m;
  const double omega = 2 * kPi * f0, k = mu * omega * omega;
  const double a2 = k * std::pow(d0, b2 + 1) / (b1 - b2), a1 = a2 * std::pow(d0, b1 - b2);
  const double dstart = d0 * (1.0 + 1e-3);
  const double T = 2 * kPi / omega, dt = T / steps_per_period;
  auto U = [&](double d) { return a1 * std::pow(d, 1 - b1) / (b1 - 1) - a2 * std::pow(d, 1 - b2) / (b2 - 1); };

  Scene s = test::make_scene(dt, 1.0);
  s.model.params.time.integrator = integ;
  s.model.params.fields.gravity = {};
  s.model.params.near_field.empirical = true;
  s.model.params.near_field.a1 = a1;
  s.model.params.near_field.b1 = b1;
  s.model.params.near_field.a2 = a2;
  s.model.params.near_field.b2 = b2;
  s.model.params.near_field.cutoff = 5e-3;
  const Vec3 axis = Vec3{1.0, 2.0, -0.5} / norm(Vec3{1.0, 2.0, -0.5});  // not along a grid axis
  test::add_particle(s, 1, R, {});
  test::add_particle(s, 2, R, dstart * axis);
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  sim.initialize();
  const Particles& p = sim.particles();
  const double E0 = U(dstart), Eosc = U(dstart) - U(d0);
  Oscillation r;
  double prev = dstart - d0, first = -1.0, last = -1.0;
  const int steps = static_cast<int>(periods * steps_per_period);
  for (int n = 0; n < steps; ++n) {
    sim.advance(dt);
    EXPECT_EQ(p.force[0], -p.force[1]);  // Newton's third law, exactly
    const double d = norm(p.x[0] - p.x[1]);
    const double E = 0.5 * m * (norm2(p.v[0]) + norm2(p.v[1])) + U(d);
    r.energy_error = std::max(r.energy_error, std::abs(E - E0) / Eosc);
    const double y = d - d0;
    if (prev > 0.0 && y <= 0.0) {  // downward crossing, linearly interpolated
      const double tc = sim.time() - dt * y / (y - prev);
      if (first < 0.0) first = tc;
      last = tc;
      ++r.crossings;
    }
    prev = y;
  }
  r.period_error = std::abs((last - first) / (r.crossings - 1) / T - 1.0);
  return r;
}
}  // namespace

TEST(NearFieldPair, SmallOscillationFrequencyAndEnergy) {
  struct Case {
    Integrator integ;
    int steps_per_period;
    const char* name;
  };
  for (const Case c : {Case{Integrator::Trapezoidal, 200, "trapezoidal"}, Case{Integrator::Verlet, 600, "verlet"}}) {
    const Oscillation r = oscillate(c.integ, c.steps_per_period, 5.2);
    EXPECT_GE(r.crossings, 5) << c.name;
    EXPECT_LT(r.period_error, 0.01) << c.name;
    EXPECT_LT(r.energy_error, 1e-4) << c.name;
    std::printf(
        "near-field pair (%s, %d steps/period): period error %.3g, energy error %.3g of the oscillation energy\n",
        c.name, c.steps_per_period, r.period_error, r.energy_error);
  }
}

// ---------------------------------------------------------------------------------------------
// Two like charges released from rest at d0: by energy conservation each reaches
//   v(d) = sqrt(kc q^2 (1/d0 - 1/d) / m)   while d < r_cut,
// and keeps v(r_cut) beyond the cutoff.

TEST(Coulomb, LikeChargesReachTheSpeedOfTheirCoulombEnergy) {
  const double R = 1e-3, q = 1e-9, d0 = 3e-3, rc = 3e-2, dt = 2e-5;
  Scene s = test::make_scene(dt, 1.0);
  s.model.params.fields.gravity = {};
  s.model.params.near_field.coulomb = true;
  s.model.params.near_field.cutoff = rc;
  test::add_particle(s, 1, R, {});
  test::add_particle(s, 2, R, {0.0, d0, 0.0});
  s.particles.charge = {q, q};
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  sim.initialize();
  const Particles& p = sim.particles();
  const double m = p.mass[0];
  auto speed = [&](double d) { return std::sqrt(kCoulomb * q * q * (1 / d0 - 1 / std::min(d, rc)) / m); };
  double worst = 0.0;
  int checked = 0;
  while (norm(p.x[0] - p.x[1]) < 1.5 * rc) {
    sim.advance(dt);
    ASSERT_LT(sim.steps(), 20000u);
    EXPECT_EQ(p.force[0], -p.force[1]);
    const double d = norm(p.x[0] - p.x[1]);
    if (d < 1.01 * d0 || (d > 0.99 * rc && d < 1.05 * rc)) continue;  // tiny speeds; the step crossing the cutoff
    worst = std::max(worst, std::abs(norm(p.v[0]) / speed(d) - 1.0));
    worst = std::max(worst, std::abs(norm(p.v[1]) / speed(d) - 1.0));
    ++checked;
  }
  const double vfinal = speed(rc);
  EXPECT_GT(checked, 100);
  EXPECT_LT(worst, 1e-3);
  EXPECT_NEAR(norm(p.v[0]), vfinal, 1e-3 * vfinal);
  EXPECT_LT(norm(p.v[0] + p.v[1]), 1e-12 * vfinal);  // momentum stays zero
  std::printf("coulomb: final speed %.9g m/s, analytic %.9g m/s, max rel. error on the way %.3g (%d steps)\n",
              norm(p.v[0]), vfinal, worst, checked);
}
