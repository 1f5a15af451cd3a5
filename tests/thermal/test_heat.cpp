// Thermal field (physics.md section 8) against closed forms: the pure laws (88)-(95), two touching
// particles relaxing to their capacity-weighted mean, a particle cooling by convection at several
// air speeds and by radiation, a particle on a fixed-temperature barrier, the heat bookkeeping of
// the global log, and a mechanical scene at uniform temperature that the thermal switch must not
// change at all.
//
// Holding particles still: the thermal tests use particles that are mechanically inert (Young's
// modulus 1e-20 Pa, gravity off, zero velocities), so the contact force of the small overlap is
// ~1e-30 N and the positions do not move (checked: |dx| < 1e-15 m). Mechanics do not depend on
// temperature (physics.md section 8), so this isolates the heat flows without special code paths.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "physics/heat.hpp"
#include "thermal/heat_transfer.hpp"
#include "sim/simulation.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kSigma = 5.670374419e-8;  // W/(m^2 K^4), CODATA

// h(v) of (93) written out independently of the engine, v already in the fit's range.
double h_fit(double v) { return 12.15335 - 1.1630 * v + 11.630 * std::sqrt(v); }

Scene thermal_scene(double dt, Integrator integ) {
  Scene s = test::make_scene(dt, 1.0);
  s.model.params.time.integrator = integ;
  s.model.params.fields.gravity = {};
  s.model.params.analysis.thermal = true;
  return s;
}

// Makes particle i mechanically inert (see the file comment).
void inert(Scene& s, std::size_t i) { test::own_material(s, i).young = 1e-20; }
}  // namespace

// ---------------------------------------------------------------------------------------------
// Pure laws

TEST(HeatLaws, LensAreaMatchesTheLensRadius) {
  // Lens radius of two spheres: a^2 = [4 d^2 Ri^2 - (d^2 - Rj^2 + Ri^2)^2] / (4 d^2).
  const double Ri = 1e-3, Rj = 1.7e-3, d = 2.6e-3;
  const double a2 = (4 * d * d * Ri * Ri - std::pow(d * d - Rj * Rj + Ri * Ri, 2)) / (4 * d * d);
  EXPECT_NEAR(contact_area_pair(d, Ri, Rj), kPi * a2, 1e-12 * kPi * a2);
  EXPECT_NEAR(contact_area_pair(d, Rj, Ri), kPi * a2, 1e-12 * kPi * a2);  // symmetric
  // Equal spheres at overlap delta: A = pi (R delta - delta^2 / 4).
  const double R = 2e-3, delta = 1e-5;
  EXPECT_NEAR(contact_area_pair(2 * R - delta, R, R), kPi * (R * delta - delta * delta / 4), 1e-9 * kPi * R * delta);
  EXPECT_EQ(contact_area_pair(2 * R + 1e-6, R, R), 0.0);  // apart: no area
  // Sphere cut by a plane at depth delta: A = pi (2 R delta - delta^2); past the centre: pi R^2.
  EXPECT_NEAR(contact_area_plane(R, delta), kPi * (2 * R * delta - delta * delta), 1e-12 * kPi * R * delta);
  EXPECT_DOUBLE_EQ(contact_area_plane(R, 3 * R), kPi * R * R);
}

TEST(HeatLaws, ConductivityConvectionRadiation) {
  EXPECT_DOUBLE_EQ(pair_conductivity(2.0, 50.0), 2.0 * 2.0 * 50.0 / 52.0);
  EXPECT_DOUBLE_EQ(pair_conductivity(3.0, 3.0), 3.0);
  EXPECT_EQ(pair_conductivity(0.0, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(conduction_heat(2.0, 3e-6, 1e-3, 300.0, 310.0), 2.0 * 3e-6 * 10.0 / 1e-3);
  // (93): h(0) = 12.15335, h(1) = 22.62035 W/m^2K; clamped to [0, 20] m/s.
  EXPECT_DOUBLE_EQ(convection_coefficient(0.0), 12.15335);
  EXPECT_NEAR(convection_coefficient(1.0), 22.62035, 1e-12);
  EXPECT_NEAR(convection_coefficient(20.0), 12.15335 - 23.26 + 11.630 * std::sqrt(20.0), 1e-12);
  EXPECT_EQ(convection_coefficient(35.0), convection_coefficient(20.0));
  EXPECT_EQ(convection_coefficient(-1.0), convection_coefficient(0.0));
  const double R = 1e-3;
  EXPECT_NEAR(convection_heat(10.0, R, 300.0, 350.0), 10.0 * 4 * kPi * R * R * (-50.0), 1e-15);
  EXPECT_NEAR(radiation_heat(0.8, R, 300.0, 1000.0), 0.8 * kSigma * 4 * kPi * R * R * (8.1e9 - 1e12),
              1e-12 * 0.8 * kSigma * 4 * kPi * R * R * 1e12);
  EXPECT_EQ(radiation_heat(0.8, R, 321.5, 321.5), 0.0);  // no heat from nothing
}

// ---------------------------------------------------------------------------------------------
// Two touching particles: dT = T1 - T2 decays as exp(-G (1/C1 + 1/C2) t), G = K A / d, towards
// the capacity-weighted mean; sum C T is conserved.

namespace {
void two_particle_relaxation(Integrator integ, double lambda_dt, double lambda_t_end) {
  const double R1 = 1e-3, R2 = 1.5e-3, delta = 1e-5;
  const double d = R1 + R2 - delta;
  Scene s = thermal_scene(1.0, integ);
  test::add_particle(s, 1, R1, {0.0, 0.0, 0.0});
  test::add_particle(s, 2, R2, {d, 0.0, 0.0});
  const double k1 = 2.0, k2 = 50.0, c1 = 800.0, c2 = 400.0;
  test::own_material(s, 0).conductivity = k1;
  test::own_material(s, 1).conductivity = k2;
  s.model.materials[static_cast<std::size_t>(s.particles.material[0])].heat_capacity = c1;
  s.model.materials[static_cast<std::size_t>(s.particles.material[1])].heat_capacity = c2;
  s.particles.T = {400.0, 300.0};
  inert(s, 0);
  inert(s, 1);
  // Closed form, computed here from the geometry (lens radius) and the masses.
  const double a2 = (4 * d * d * R1 * R1 - std::pow(d * d - R2 * R2 + R1 * R1, 2)) / (4 * d * d);
  const double K = 2 * k1 * k2 / (k1 + k2), A = kPi * a2, G = K * A / d;
  const double C1 = 4.0 / 3.0 * kPi * R1 * R1 * R1 * 2500.0 * c1, C2 = 4.0 / 3.0 * kPi * R2 * R2 * R2 * 2500.0 * c2;
  const double lambda = G * (1 / C1 + 1 / C2);
  const double Tmean = (C1 * 400.0 + C2 * 300.0) / (C1 + C2);
  const double dt = lambda_dt / lambda;
  const int steps = static_cast<int>(std::ceil(lambda_t_end / lambda_dt));
  s.model.params.time.dt = dt;

  Simulation sim(std::move(s), RunOptions{{}, false, false});
  Particles& p = sim.particles();
  sim.initialize();
  const std::size_t i1 = p.id[0] == 1 ? 0 : 1, i2 = 1 - i1;  // initialize may reorder
  const double E0 = C1 * 400.0 + C2 * 300.0;
  const Vec3 x1 = p.x[i1], x2 = p.x[i2];
  double worst = 0.0, worst_energy = 0.0;
  for (int k = 0; k < steps; ++k) {
    sim.advance(dt);
    const double exact = 100.0 * std::exp(-lambda * sim.time());
    worst = std::max(worst, std::abs((p.T[i1] - p.T[i2]) / exact - 1.0));
    const auto c = [&](std::size_t i) {
      return sim.model().materials[static_cast<std::size_t>(p.material[i])].heat_capacity;
    };
    const double E = p.mass[i1] * c(i1) * p.T[i1] + p.mass[i2] * c(i2) * p.T[i2];
    worst_energy = std::max(worst_energy, std::abs(E / E0 - 1.0));
    ASSERT_GT(p.T[i1], Tmean);  // monotone approach from above ...
    ASSERT_LT(p.T[i2], Tmean);  // ... and below
  }
  EXPECT_LT(worst, 1e-3) << "relative error of T1 - T2 against exp(-lambda t), lambda = " << lambda;
  EXPECT_LT(worst_energy, 1e-12);
  EXPECT_LT(norm(p.x[i1] - x1) + norm(p.x[i2] - x2), 1e-15);  // held still (mechanically inert)
  std::printf("two particles (%s): lambda = %.6g 1/s, max rel. error of dT %.3g, of sum C T %.3g\n",
              integ == Integrator::Verlet ? "verlet" : "trapezoidal", lambda, worst, worst_energy);
}
}  // namespace

TEST(Conduction, TwoParticlesRelaxToWeightedMeanTrapezoidal) {
  // Trapezoidal: per-step phase error (lambda dt)^3 / 12; 250 steps to lambda t = 5.
  two_particle_relaxation(Integrator::Trapezoidal, 0.02, 5.0);
}

TEST(Conduction, TwoParticlesRelaxToWeightedMeanVerlet) {
  // Verlet integrates T with explicit Euler: error lambda t * lambda dt / 2; lambda dt = 2e-4.
  two_particle_relaxation(Integrator::Verlet, 2e-4, 4.0);
}

// ---------------------------------------------------------------------------------------------
// Convection: tau = rho c R / (3 h(v)) for |v_i - v_air| = 0, 1, 5, 10, 20 m/s.

namespace {
struct CoolingResult {
  double worst = 0.0;    // max relative error of T - T_air against the exponential
  double balance = 0.0;  // max |sum m c T + convected - E0| / E0
};

CoolingResult convective_cooling(double v_particle, double v_air, double h_expected) {
  const double R = 1e-3, rho = 2500.0, c = 800.0, Tair = 300.0, T0 = 350.0;
  const double tau = rho * c * R / (3.0 * h_expected);
  const double dt = 0.01 * tau;
  Scene s = thermal_scene(dt, Integrator::Trapezoidal);
  s.model.params.thermal.conduction = false;
  s.model.params.thermal.convection = true;
  s.model.params.thermal.air_temperature = Tair;
  s.model.params.thermal.air_velocity = {v_air, 0.0, 0.0};
  test::add_particle(s, 1, R, {}, {v_particle, 0.0, 0.0});
  test::own_material(s, 0).heat_capacity = c;
  s.particles.T[0] = T0;
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  sim.initialize();
  const double E0 = sim.particles().mass[0] * c * T0;
  CoolingResult r;
  for (int k = 0; k < 300; ++k) {  // 3 tau
    sim.advance(dt);
    const double exact = (T0 - Tair) * std::exp(-sim.time() / tau);
    r.worst = std::max(r.worst, std::abs((sim.particles().T[0] - Tair) / exact - 1.0));
    const double E = thermal_energy(sim.model(), sim.particles()) + sim.interactions().stats().heat_convected;
    r.balance = std::max(r.balance, std::abs(E / E0 - 1.0));
  }
  return r;
}
}  // namespace

TEST(Convection, LumpedExponentialAtSeveralAirSpeeds) {
  for (double v : {0.0, 1.0, 5.0, 10.0, 20.0}) {
    // Half of the cases move the particle, half the air: only the relative speed counts.
    const bool move_air = v == 5.0 || v == 20.0;
    const CoolingResult r = convective_cooling(move_air ? 0.0 : v, move_air ? -v : 0.0, h_fit(v));
    EXPECT_LT(r.worst, 1e-3) << "v = " << v;
    EXPECT_LT(r.balance, 1e-12) << "v = " << v;  // heat_convected balances the stored energy
    std::printf("convection v = %4.1f m/s: h = %.6g W/m2K, max rel. error %.3g, balance %.3g\n", v, h_fit(v), r.worst,
                r.balance);
  }
}

TEST(Convection, SpeedAboveTheFitIsClampedWithOneWarning) {
  testing::internal::CaptureStderr();
  const CoolingResult r = convective_cooling(30.0, 0.0, h_fit(20.0));  // behaves as 20 m/s
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_LT(r.worst, 1e-3);
  const std::string key = "convection fit (93)";
  const std::size_t first = err.find(key);
  ASSERT_NE(first, std::string::npos) << err;
  EXPECT_EQ(err.find(key, first + 1), std::string::npos) << "warning printed more than once";
}

// ---------------------------------------------------------------------------------------------
// Radiation: m c dT/dt = -eps sigma A (T^4 - Te^4) has the implicit solution
//   t(T) = m c / (eps sigma A) [F(T0) - F(T)],  F(T) = -[atanh(Te/T) + atan(T/Te)] / (2 Te^3).

namespace {
double radiation_time(double T, double T0, double Te, double scale) {
  auto F = [Te](double x) { return -(std::atanh(Te / x) + std::atan(x / Te)) / (2.0 * Te * Te * Te); };
  return scale * (F(T0) - F(T));
}
}  // namespace

TEST(Radiation, ClosedFormCooling) {
  const double R = 1e-3, rho = 2500.0, c = 800.0, eps = 0.9, Te = 300.0, T0 = 1000.0;
  const double scale = rho * c * R / (3.0 * eps * kSigma);  // m c / (eps sigma A), K^3 s
  const double dt = 0.01;                                   // s; linearised rate 4 T^3/scale <= 0.31 1/s
  Scene s = thermal_scene(dt, Integrator::Trapezoidal);
  s.model.params.thermal.conduction = false;
  s.model.params.thermal.radiation = true;
  s.model.params.thermal.environment_temperature = Te;
  test::add_particle(s, 1, R, {});
  {
    Material& m = test::own_material(s, 0);
    m.heat_capacity = c;
    m.emissivity = eps;
  }
  s.particles.T[0] = T0;
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  sim.initialize();
  const double E0 = sim.particles().mass[0] * c * T0;
  double worst = 0.0, worst_t = 0.0, balance = 0.0;
  for (int k = 0; k < 3000; ++k) {  // 30 s: from 1000 K down to ~ 510 K
    sim.advance(dt);
    const double T = sim.particles().T[0];
    // Exact T at the simulated time, by bisection on the monotone t(T).
    double lo = Te * (1 + 1e-12), hi = T0;
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      (radiation_time(mid, T0, Te, scale) > sim.time() ? lo : hi) = mid;
    }
    const double exact = 0.5 * (lo + hi);
    worst = std::max(worst, std::abs((T - Te) / (exact - Te) - 1.0));  // relative to the excess over Te
    worst_t = std::max(worst_t, std::abs(radiation_time(T, T0, Te, scale) / sim.time() - 1.0));
    balance = std::max(
        balance,
        std::abs((thermal_energy(sim.model(), sim.particles()) + sim.interactions().stats().heat_radiated) / E0 - 1.0));
  }
  EXPECT_LT(worst, 1e-3);
  EXPECT_LT(worst_t, 1e-3);
  EXPECT_LT(balance, 1e-12);
  EXPECT_LT(sim.particles().T[0], 550.0);  // it really cooled
  std::printf("radiation: T(30 s) = %.6f K, max rel. error of T - Te %.3g, of t(T) %.3g, balance %.3g\n",
              sim.particles().T[0], worst, worst_t, balance);
}

// ---------------------------------------------------------------------------------------------
// A particle resting on a barrier held at T_b: T - T_b decays at rate k A_b / (d_b C),
// A_b = pi (R^2 - (R - delta)^2), d_b = R - delta; the heat goes into the barrier.

TEST(Conduction, ParticleOnFixedTemperatureBarrier) {
  const double R = 1e-3, delta = 2e-6, k = 5.0, c = 800.0, Tb = 500.0, T0 = 300.0;
  const double Ab = kPi * (R * R - (R - delta) * (R - delta)), db = R - delta;
  const double C = 4.0 / 3.0 * kPi * R * R * R * 2500.0 * c;
  const double lambda = k * Ab / (db * C);
  const double dt = 0.02 / lambda;
  Scene s = thermal_scene(dt, Integrator::Trapezoidal);
  // The balance below holds to the fixed-point tolerance (the accepted T used the rate of the
  // last iteration, the log the rate at the accepted T): TOL_T = 1e-8 leaves ~7e-11 here.
  s.model.params.tolerance.temperature = 1e-13;
  s.model.params.tolerance.temperature_floor = 1e-15;  // K
  Barriers& b = s.barriers;
  const int g = b.group_index("floor");
  ASSERT_TRUE(b.add(1, {-0.01, -0.01, 0}, {0.01, -0.01, 0}, {0.01, 0.01, 0}, g, 1e-20, 0.3, MotionLaw{}, 0.0, Tb));
  ASSERT_TRUE(b.add(2, {-0.01, -0.01, 0}, {0.01, 0.01, 0}, {-0.01, 0.01, 0}, g, 1e-20, 0.3, MotionLaw{}, 0.0, Tb));
  test::add_particle(s, 1, R, {0.002, 0.001, R - delta});  // over the middle of element 1
  {
    Material& m = test::own_material(s, 0);
    m.conductivity = k;
    m.heat_capacity = c;
  }
  s.particles.T[0] = T0;
  inert(s, 0);
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  sim.initialize();
  const double E0 = sim.particles().mass[0] * c * T0;
  double worst = 0.0, balance = 0.0;
  for (int n = 0; n < 200; ++n) {  // lambda t = 4
    sim.advance(dt);
    const double exact = (T0 - Tb) * std::exp(-lambda * sim.time());
    worst = std::max(worst, std::abs((sim.particles().T[0] - Tb) / exact - 1.0));
    balance = std::max(
        balance,
        std::abs((thermal_energy(sim.model(), sim.particles()) + sim.interactions().stats().heat_to_barriers) / E0 -
                 1.0));
  }
  EXPECT_EQ(sim.interactions().stats().contacts_pb, 1u);
  EXPECT_LT(worst, 1e-3);
  EXPECT_LT(balance, 1e-12);
  EXPECT_LT(sim.interactions().stats().heat_to_barriers, 0.0);  // the barrier heated the particle
  std::printf("barrier: lambda = %.6g 1/s, max rel. error %.3g, balance %.3g\n", lambda, worst, balance);
}

// ---------------------------------------------------------------------------------------------
// No heat from nothing: a mechanical scene (grains falling onto a floor and onto each other) at
// one uniform temperature, with conduction, convection (air at that temperature), radiation
// (surroundings at that temperature) and a floor held at that temperature. Temperatures must
// stay exactly uniform and the mechanics bitwise identical to the run with thermal off.

namespace {
Scene mechanical_scene(bool thermal, Integrator integ) {
  const double T = 321.25;
  Scene s = test::make_scene(5e-6, 1.0);
  s.model.params.time.integrator = integ;
  s.model.params.analysis.thermal = thermal;
  s.model.params.contact.particle_particle.restitution = 0.6;
  s.model.params.contact.particle_barrier.restitution = 0.6;
  s.model.params.thermal = {T, {0.3, 0.0, 0.0}, T, true, true, true};
  s.model.materials[0].young = 1e7;
  Barriers& b = s.barriers;
  const int g = b.group_index("floor");
  b.add(1, {-0.02, -0.02, 0}, {0.02, -0.02, 0}, {0.02, 0.02, 0}, g, 1e7, 0.3, MotionLaw{}, 0.0, T);
  b.add(2, {-0.02, -0.02, 0}, {0.02, 0.02, 0}, {-0.02, 0.02, 0}, g, 1e7, 0.3, MotionLaw{}, 0.0, T);
  // 3 x 3 x 3 spheres, initially apart (gaps >= 0.15 mm); upper layers fall faster and the lower
  // ones spread sideways, so they hit the floor and each other within a few milliseconds.
  std::int64_t id = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        const double jitter = 1e-5 * ((i * 7 + j * 3 + k) % 5);
        const std::size_t n = test::add_particle(s, ++id, 1e-3 * (1.0 + 0.05 * k),
                                                 {0.0025 * i + jitter, 0.0025 * j, 0.0012 + 0.0023 * k},
                                                 {0.05 * (i - 1), -0.04 * (j - 1), -0.05 - 0.1 * k});
        s.particles.T[n] = T;
        Material& m = test::own_material(s, n);  // varied properties must not matter
        m.conductivity = 1.0 + 0.5 * i;
        m.emissivity = 0.5 + 0.1 * j;
      }
  return s;
}
}  // namespace

TEST(NoHeatFromNothing, UniformTemperatureStaysUniformAndMechanicsUnchanged) {
  for (Integrator integ : {Integrator::Trapezoidal, Integrator::Verlet}) {
    Scene on = mechanical_scene(true, integ), off = mechanical_scene(false, integ);
    Simulation a(std::move(on), RunOptions{{}, false, false}), b(std::move(off), RunOptions{{}, false, false});
    std::size_t max_contacts = 0;
    for (int k = 0; k < 1200; ++k) {
      const StepReport ra = a.advance(5e-6), rb = b.advance(5e-6);
      ASSERT_EQ(ra.iterations, rb.iterations) << "step " << k;
      max_contacts = std::max(max_contacts,
                              a.interactions().stats().contacts_pp + a.interactions().stats().contacts_pb);
    }
    EXPECT_GT(max_contacts, 9u);  // the scene really has contacts that conduct
    std::printf("uniform temperature (%s): up to %zu contacts, mechanics bitwise equal, T exactly uniform\n",
                integ == Integrator::Verlet ? "verlet" : "trapezoidal", max_contacts);
    const Particles &p = a.particles(), &q = b.particles();
    ASSERT_EQ(p.size(), q.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
      ASSERT_EQ(p.id[i], q.id[i]);
      EXPECT_EQ(p.x[i], q.x[i]) << "particle " << p.id[i];  // bitwise
      EXPECT_EQ(p.v[i], q.v[i]);
      EXPECT_EQ(p.w[i], q.w[i]);
      EXPECT_EQ(p.T[i], 321.25);  // exactly
      EXPECT_EQ(p.heat[i], 0.0);
    }
    const InteractionStats& st = a.interactions().stats();
    EXPECT_EQ(st.heat_to_barriers, 0.0);
    EXPECT_EQ(st.heat_convected, 0.0);
    EXPECT_EQ(st.heat_radiated, 0.0);
  }
}
