// Head-on sphere-sphere impacts through the whole engine against closed forms (physics.md sections 5, 6, 12):
// Hertz peak force, overlap, contact time and velocity exchange; restitution; five-sphere chain, wave ~ E^(-2/5).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>
#include <vector>

#include "sim/simulation.hpp"
#include "support/barrier_mechanics_scene.hpp"
#include "support/contact_scenes.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;
using namespace mpdem::test;  // kR, kE, kNu, kRho, sphere_mass, name, base_scene

namespace {

// Hertz closed forms of an undamped impact (docs/contact_model.md), written out here
// independently of the engine.
struct HertzClosedForm {
  double delta_max;  // m
  double F_max;      // N
  double t_c;        // s
};
HertzClosedForm hertz_closed_form(double m_star, double E_star, double r_star, double v) {
  HertzClosedForm h;
  h.delta_max = std::pow(15.0 * m_star * v * v / (16.0 * E_star * std::sqrt(r_star)), 0.4);
  h.F_max = 4.0 / 3.0 * E_star * std::sqrt(r_star) * std::pow(h.delta_max, 1.5);
  h.t_c = 2.943275 * h.delta_max / v;
  return h;
}

// E* of two equal spheres of the test material, (51)
double pair_E_star() { return kE / (2.0 * (1.0 - kNu * kNu)); }

struct ImpactResult {
  double F_max = 0.0;           // N, largest |force| on sphere 1 during contact
  double delta_max = 0.0;       // m
  double t_c = 0.0;             // s, from the interpolated zero crossings of the overlap
  double v1 = 0.0, v2 = 0.0;    // m/s, x-velocities after separation
  double momentum_error = 0.0;  // |P_end - P_0| / (m v)
};

// Head-on impact of two equal spheres along x, closing speed v; restitution e (1: no damping).
// Sphere 2 may have its own elastic constants (E2, nu2; E_star is then the pair's).
ImpactResult head_on(Integrator integ, double v, double e, double steps_per_tc, double E2 = kE, double nu2 = kNu) {
  const double m = sphere_mass(kR);
  const double E_star = 1.0 / ((1.0 - kNu * kNu) / kE + (1.0 - nu2 * nu2) / E2);  // (51)
  const HertzClosedForm h = hertz_closed_form(0.5 * m, E_star, 0.5 * kR, v);
  const double dt = h.t_c / steps_per_tc;
  Scene s = base_scene(integ, dt, {});  // no gravity
  if (e < 1.0) s.model.params.contact.particle_particle.restitution = e;
  else s.model.params.contact.particle_particle.damping_ratio = 0.0;
  const double gap = 3.3 * v * dt;  // contact starts within a few steps
  test::add_particle(s, 1, kR, {-kR - 0.5 * gap, 0.0, 0.0}, {0.5 * v, 0.0, 0.0});
  const std::size_t second = test::add_particle(s, 2, kR, {kR + 0.5 * gap, 0.0, 0.0}, {-0.5 * v, 0.0, 0.0});
  if (E2 != kE || nu2 != kNu) test::give_own_material(s, second, E2, nu2);
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  Particles& p = sim.particles();
  const Vec3 P0 = test::momentum(p);
  ImpactResult r;
  double ov_prev = -gap, t_start = -1.0;
  for (int k = 0; k < 20 * static_cast<int>(steps_per_tc); ++k) {
    sim.advance(dt);
    const std::size_t a = test::index_of(p, 1), b = test::index_of(p, 2);
    const double ov = 2.0 * kR - norm(p.x[a] - p.x[b]);
    if (ov > 0.0) {
      r.F_max = std::max(r.F_max, norm(p.force[a]));
      r.delta_max = std::max(r.delta_max, ov);
    }
    const double t = sim.time();
    if (ov_prev <= 0.0 && ov > 0.0 && t_start < 0.0) t_start = t - dt * ov / (ov - ov_prev);
    if (ov_prev > 0.0 && ov <= 0.0) {
      r.t_c = (t - dt * (-ov) / (ov_prev - ov)) - t_start;
      r.v1 = p.v[a].x;
      r.v2 = p.v[b].x;
      r.momentum_error = norm(test::momentum(p) - P0) / (m * v);
      break;
    }
    ov_prev = ov;
  }
  return r;
}

struct ChainResult {
  double travel = 0.0;          // s, first contact -> last sphere's departure
  double momentum_error = 0.0;  // max |P - P0| / |P0|
  double energy_error = 0.0;    // max |E - E0| / E0, E = kinetic + rotational + elastic
};

// Five equal spheres along x, touching (zero overlap); the first one arrives with speed v.
ChainResult five_chain(Integrator integ, double E, double steps_per_tc) {
  const double v = 0.5, m = sphere_mass(kR);
  const double Es = E / (2.0 * (1.0 - kNu * kNu));
  const HertzClosedForm h = hertz_closed_form(0.5 * m, Es, 0.5 * kR, v);
  const double dt = h.t_c / steps_per_tc;
  Scene s = base_scene(integ, dt, {});  // no gravity
  test::set_material(s, kRho, E, kNu);
  s.model.params.contact.particle_particle.damping_ratio = 0.0;  // e = 1
  const double gap = 2.5 * v * dt;
  test::add_particle(s, 1, kR, {-2.0 * kR - gap, 0, 0}, {v, 0, 0});
  for (int k = 0; k < 4; ++k) test::add_particle(s, 2 + k, kR, {2.0 * kR * k, 0, 0});
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  Particles& p = sim.particles();
  auto energy = [&] {
    double K = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
      K += 0.5 * p.mass[i] * norm2(p.v[i]) + 0.5 * p.inertia[i] * norm2(p.w[i]);
    return K + sim.interactions().stats().elastic_energy;
  };
  const Vec3 P0 = test::momentum(p);
  const double E0 = energy();
  ChainResult r;
  double first = -1.0, last_end = -1.0, ov01_prev = -gap, ov45_prev = 0.0;
  const int steps = static_cast<int>(12.0 * steps_per_tc);
  for (int k = 0; k < steps; ++k) {
    sim.advance(dt);
    const double t = sim.time();
    r.momentum_error = std::max(r.momentum_error, norm(test::momentum(p) - P0) / norm(P0));
    r.energy_error = std::max(r.energy_error, std::abs(energy() - E0) / E0);
    const std::size_t i1 = test::index_of(p, 1), i2 = test::index_of(p, 2), i4 = test::index_of(p, 4),
                      i5 = test::index_of(p, 5);
    const double ov01 = 2.0 * kR - norm(p.x[i1] - p.x[i2]);
    const double ov45 = 2.0 * kR - norm(p.x[i4] - p.x[i5]);
    if (first < 0.0 && ov01_prev <= 0.0 && ov01 > 0.0) first = t - dt * ov01 / (ov01 - ov01_prev);
    if (ov45_prev > 0.0 && ov45 <= 0.0) last_end = t - dt * (-ov45) / (ov45_prev - ov45);
    ov01_prev = ov01;
    ov45_prev = ov45;
  }
  r.travel = last_end - first;
  return r;
}

}  // namespace

// Head-on elastic impact: peak force and maximum overlap within 0.5%, contact time within 1% of
// the Hertz closed forms; the velocities are exchanged (within 1e-4 of v, e = 1).
TEST(HeadOnImpact, MatchesHertzClosedForms) {
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    for (double v : {0.1, 1.0}) {
      const double m = sphere_mass(kR);
      const HertzClosedForm h = hertz_closed_form(0.5 * m, pair_E_star(), 0.5 * kR, v);
      const ImpactResult r = head_on(integ, v, 1.0, 1000.0);
      const double eF = r.F_max / h.F_max - 1.0, eD = r.delta_max / h.delta_max - 1.0, eT = r.t_c / h.t_c - 1.0;
      RecordProperty(std::string("rel_err_") + name(integ) + "_v" + std::to_string(v),
                     std::to_string(eF) + " " + std::to_string(eD) + " " + std::to_string(eT));
      std::printf("[%s v=%g] F_max err %.2e, delta_max err %.2e, t_c err %.2e, v1 %.6f v2 %.6f\n", name(integ), v, eF,
                  eD, eT, r.v1, r.v2);
      EXPECT_LT(std::abs(eF), 0.005) << name(integ);
      EXPECT_LT(std::abs(eD), 0.005) << name(integ);
      EXPECT_LT(std::abs(eT), 0.01) << name(integ);
      // Exchange: sphere 1 leaves with -v/2, sphere 2 with +v/2.
      EXPECT_NEAR(r.v1, -0.5 * v, 1e-4 * v) << name(integ);
      EXPECT_NEAR(r.v2, 0.5 * v, 1e-4 * v) << name(integ);
      EXPECT_LT(r.momentum_error, 1e-12);  // pair forces are equal and opposite
    }
  }
}

// Two materials (E 1e7 and 4e7 Pa, nu 0.3 and 0.2): the pair kernel's general path, which forms
// E* (51) and G* from both particles' constants (one material takes a path with constant E*, G*).
// Same closed forms and tolerances as above, with the pair's E*.
TEST(HeadOnImpact, TwoMaterialsMatchHertzWithThePairModulus) {
  const double E2 = 4.0 * kE, nu2 = 0.2;
  const double E_star = 1.0 / ((1.0 - kNu * kNu) / kE + (1.0 - nu2 * nu2) / E2);
  ASSERT_GT(E_star / pair_E_star(), 1.5);  // clearly not the one-material value
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const double v = 1.0, m = sphere_mass(kR);
    const HertzClosedForm h = hertz_closed_form(0.5 * m, E_star, 0.5 * kR, v);
    const ImpactResult r = head_on(integ, v, 1.0, 1000.0, E2, nu2);
    const double eF = r.F_max / h.F_max - 1.0, eD = r.delta_max / h.delta_max - 1.0, eT = r.t_c / h.t_c - 1.0;
    std::printf("[%s two materials] F_max err %.2e, delta_max err %.2e, t_c err %.2e\n", name(integ), eF, eD, eT);
    EXPECT_LT(std::abs(eF), 0.005) << name(integ);
    EXPECT_LT(std::abs(eD), 0.005) << name(integ);
    EXPECT_LT(std::abs(eT), 0.01) << name(integ);
    EXPECT_NEAR(r.v1, -0.5 * v, 1e-4 * v) << name(integ);
    EXPECT_NEAR(r.v2, 0.5 * v, 1e-4 * v) << name(integ);
  }
}

// Achieved restitution (separation / approach speed) within 0.005 of the requested e, for
// e in {0.1 ... 1} and impact speeds 0.01 ... 10 m/s; dt = t_c / 200.
TEST(Restitution, SphereSphereSweep) {
  double worst = 0.0;
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal})
    for (double e : {0.1, 0.3, 0.5, 0.7, 0.9, 1.0})
      for (double v : {0.01, 0.1, 1.0, 10.0}) {
        const ImpactResult r = head_on(integ, v, e, 200.0);
        const double achieved = (r.v2 - r.v1) / v;
        worst = std::max(worst, std::abs(achieved - e));
        EXPECT_NEAR(achieved, e, 0.005) << name(integ) << " e " << e << " v " << v;
      }
  std::printf("restitution sphere-sphere: worst |e_achieved - e| = %.2e\n", worst);
}

// Five-sphere chain, e = 1: momentum (1e-6) and kinetic + elastic energy (1e-6) conserved; the
// travel time of the wave scales as E^(-2/5) (least-squares exponent over E = 1e6 ... 1e10 Pa
// within 0.02).
TEST(FiveSphereChain, ConservationAndWaveTimeScaling) {
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    std::vector<double> lx, ly;
    for (double E : {1e6, 1e7, 1e8, 1e9, 1e10}) {
      const ChainResult r = five_chain(integ, E, 1500.0);
      std::printf("[%s] E %.0e: travel %.6e s, momentum err %.2e, energy err %.2e\n", name(integ), E, r.travel,
                  r.momentum_error, r.energy_error);
      EXPECT_GT(r.travel, 0.0);
      EXPECT_LT(r.momentum_error, 1e-6);
      EXPECT_LT(r.energy_error, 1e-6);
      lx.push_back(std::log(E));
      ly.push_back(std::log(r.travel));
    }
    const double n = static_cast<double>(lx.size());
    const double mx = std::accumulate(lx.begin(), lx.end(), 0.0) / n,
                 my = std::accumulate(ly.begin(), ly.end(), 0.0) / n;
    double sxy = 0.0, sxx = 0.0;
    for (std::size_t k = 0; k < lx.size(); ++k) {
      sxy += (lx[k] - mx) * (ly[k] - my);
      sxx += (lx[k] - mx) * (lx[k] - mx);
    }
    const double slope = sxy / sxx;
    std::printf("[%s] wave time exponent %.6f (expected -0.4)\n", name(integ), slope);
    EXPECT_NEAR(slope, -0.4, 0.02) << name(integ);
  }
}
