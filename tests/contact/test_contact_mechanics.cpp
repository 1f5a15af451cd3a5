// Particle-particle contact mechanics through the whole engine (Simulation + Interactions +
// ParticleContacts), against closed forms (physics.md sections 5, 6, 12):
//   - head-on elastic Hertz impact: peak force, maximum overlap, contact time, velocity exchange;
//   - achieved restitution over e x impact speed;
//   - Newton's third law pair by pair, torque arms (62), force and angular-momentum balance of a
//     frictional cluster, invariance under relabelling;
//   - five-sphere chain: momentum and energy conservation, wave time ~ E^(-2/5).
// Both integrators (velocity Verlet, trapezoidal phi = 0.5) wherever a run is cheap.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "sim/simulation.hpp"
#include "support/contact_scenes.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;

namespace {

constexpr double kRho = 2500.0;  // kg/m^3
constexpr double kE = 1e7;       // Pa
constexpr double kNu = 0.3;      // -
constexpr double kR = 0.005;     // m
const double kPi = std::acos(-1.0);

double sphere_mass(double R) { return 4.0 / 3.0 * kPi * R * R * R * kRho; }

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

Scene base_scene(Integrator integ, double dt) {
  Scene s = test::make_scene(dt, 1.0);
  s.model.params.time.integrator = integ;
  s.model.params.time.phi = 0.5;
  s.model.params.fields.gravity = {};
  s.model.params.tolerance.position = 1e-10;
  s.model.params.tolerance.velocity = 1e-10;
  test::set_material(s, kRho, kE, kNu);
  // These tests check the laws at finite overlaps (soft spheres, fast impacts): the overlap
  // instability check would stop them; it is tested in test_instability.cpp.
  s.model.params.checks.max_overlap = 0.0;
  return s;
}

struct ImpactResult {
  double F_max = 0.0;      // N, largest |force| on sphere 1 during contact
  double delta_max = 0.0;  // m
  double t_c = 0.0;        // s, from the interpolated zero crossings of the overlap
  double v1 = 0.0, v2 = 0.0;  // m/s, x-velocities after separation
  double momentum_error = 0.0;  // |P_end - P_0| / (m v)
};

// Head-on impact of two equal spheres along x, closing speed v; restitution e (1: no damping).
// Sphere 2 may have its own elastic constants (E2, nu2; E_star is then the pair's).
ImpactResult head_on(Integrator integ, double v, double e, double steps_per_tc, double E2 = kE, double nu2 = kNu) {
  const double m = sphere_mass(kR);
  const double E_star = 1.0 / ((1.0 - kNu * kNu) / kE + (1.0 - nu2 * nu2) / E2);  // (51)
  const HertzClosedForm h = hertz_closed_form(0.5 * m, E_star, 0.5 * kR, v);
  const double dt = h.t_c / steps_per_tc;
  Scene s = base_scene(integ, dt);
  if (e < 1.0)
    s.model.params.contact.particle_particle.restitution = e;
  else
    s.model.params.contact.particle_particle.damping_ratio = 0.0;
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

const char* name(Integrator i) { return i == Integrator::Verlet ? "verlet" : "trapezoidal"; }

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
      std::printf("[%s v=%g] F_max err %.2e, delta_max err %.2e, t_c err %.2e, v1 %.6f v2 %.6f\n", name(integ), v,
                  eF, eD, eT, r.v1, r.v2);
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

namespace {

// Two spheres in an oblique, spinning, frictional contact (no gravity).
Scene oblique_pair(Integrator integ, double dt, double mu_r) {
  Scene s = base_scene(integ, dt);
  ContactLawParams& c = s.model.params.contact.particle_particle;
  c.restitution = 0.5;
  c.mu_static = 0.5;
  c.mu_dynamic = 0.4;
  c.mu_rolling = mu_r;
  c.tangential_damping = 0.2;
  test::add_particle(s, 1, kR, {0.0, 0.0, 0.0}, {0.3, 0.05, 0.0}, {10.0, -40.0, 25.0});
  test::add_particle(s, 2, 0.7 * kR, {1.69 * kR, 0.4 * kR, 0.2 * kR}, {-0.2, 0.0, 0.03}, {-5.0, 0.0, 60.0});
  return s;
}

}  // namespace

// Newton's third law and the torque arms (62) pair by pair: f_2 = -f_1 exactly; with mu_r = 0
// the torques are r_Pi x f (r_P1 = -R_1 n, r_P2 = +R_2 n); with rolling resistance (equal and
// opposite) the torque sum is still (r_P1 - r_P2) x f. Relative tolerance 1e-12.
TEST(NewtonThirdLaw, PairForcesAndTorques) {
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal})
    for (double mu_r : {0.0, 0.1}) {
      const double dt = 2e-6;
      Scene s = oblique_pair(integ, dt, mu_r);
      Simulation sim(std::move(s), RunOptions{{}, false, false});
      Particles& p = sim.particles();
      int touching = 0;
      for (int k = 0; k < 400; ++k) {
        sim.advance(dt);
        const std::size_t a = test::index_of(p, 1), b = test::index_of(p, 2);
        const Vec3 d = p.x[a] - p.x[b];
        const double ov = p.radius[a] + p.radius[b] - norm(d);
        if (ov <= 0.0) continue;
        ++touching;
        const Vec3 n = d / norm(d);
        const Vec3 f = p.force[a];
        const double scale = norm(f) * kR;
        ASSERT_LT(norm(f + p.force[b]), 1e-12 * norm(f));
        const Vec3 expected_sum = cross(-(p.radius[a] + p.radius[b]) * n, f);
        ASSERT_LT(norm(p.torque[a] + p.torque[b] - expected_sum), 1e-12 * scale) << "step " << k;
        if (mu_r == 0.0) {
          ASSERT_LT(norm(p.torque[a] - cross(-p.radius[a] * n, f)), 1e-12 * scale);
          ASSERT_LT(norm(p.torque[b] - cross(p.radius[b] * n, -f)), 1e-12 * scale);
        }
        // The tangential force is really there (the test exercises friction).
        if (touching == 20) {
          EXPECT_GT(norm(f - dot(f, n) * n), 1e-3 * norm(f));
        }
      }
      EXPECT_GT(touching, 50) << name(integ);
    }
}

namespace {

// A compressed frictional cluster: 3 x 3 x 2 spheres of alternating radii on a lattice closer
// than touching, random velocities and spins, gravity g. `perm` relabels: input position k holds
// particle perm[k], whose id is 100 + 7 * perm[k]... (ids are permuted too).
Scene cluster(Integrator integ, double dt, const std::vector<int>& order, const std::vector<std::int64_t>& ids) {
  Scene s = base_scene(integ, dt);
  s.model.params.fields.gravity = {0.5, -1.0, -9.81};
  ContactLawParams& c = s.model.params.contact.particle_particle;
  c.damping_ratio = 0.0;  // elastic normal law: f_n is the Hertz force (bound below)
  c.mu_static = 0.4;
  c.mu_dynamic = 0.3;
  c.mu_rolling = 0.05;
  c.tangential_damping = 0.3;
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  struct Init { double R; Vec3 x, v, w; };
  std::vector<Init> init;
  for (int k = 0; k < 18; ++k) {
    const int i = k % 3, j = (k / 3) % 3, l = k / 9;
    const double R = (k % 2 == 0) ? kR : 0.8 * kR;
    const Vec3 x = Vec3{1.75 * kR * i, 1.75 * kR * j, 1.75 * kR * l} + 0.05 * kR * Vec3{U(rng), U(rng), U(rng)};
    init.push_back({R, x, 0.2 * Vec3{U(rng), U(rng), U(rng)}, 50.0 * Vec3{U(rng), U(rng), U(rng)}});
  }
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Init& q = init[static_cast<std::size_t>(order[k])];
    test::add_particle(s, ids[static_cast<std::size_t>(order[k])], q.R, q.x, q.v, q.w);
  }
  return s;
}

std::vector<int> identity(int n) {
  std::vector<int> v(static_cast<std::size_t>(n));
  std::iota(v.begin(), v.end(), 0);
  return v;
}

}  // namespace

// Force and angular-momentum balance of the cluster. Sum of forces = sum m g (relative 1e-12 of
// sum |f|) at every step. Angular momentum about the origin: the external torque integrates in
// closed form because the centre of mass moves on the exact parabola, dL_ext = M (x_c0 x g) t +
// M (v_c0 x g) t^2/2. The contact points of (62) sit at -R_i n and +R_j n, which differ by the
// overlap delta, so each frictional pair adds -delta n x f_t to dL/dt (inherent to (62)); the
// residual must stay within the bound integral sum_pairs delta mu_s F_hertz(delta) dt. A wrong
// arm or sign would give residuals ~ R f_t, i.e. R/delta ~ 100x larger.
TEST(NewtonThirdLaw, ClusterForceAndAngularMomentumBalance) {
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const double dt = 1e-6;
    std::vector<std::int64_t> ids(18);
    std::iota(ids.begin(), ids.end(), 1);
    Scene s = cluster(integ, dt, identity(18), ids);
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    Particles& p = sim.particles();
    const Vec3 g = sim.model().params.fields.gravity;
    double M = 0.0;
    Vec3 xc0{}, vc0{};
    for (std::size_t i = 0; i < p.size(); ++i) {
      M += p.mass[i];
      xc0 += p.mass[i] * p.x[i];
      vc0 += p.mass[i] * p.v[i];
    }
    xc0 = xc0 / M;
    vc0 = vc0 / M;
    const Vec3 L0 = test::angular_momentum(p);
    const double mu_s = 0.4;
    double bound = 0.0, arm_scale = 0.0;  // N m s: integral of sum delta mu_s F and of sum R mu_s F
    std::size_t max_contacts = 0;
    for (int k = 0; k < 1500; ++k) {
      sim.advance(dt);
      Vec3 F{}, W{};
      double Fabs = 0.0, pair_bound = 0.0, pair_arm = 0.0;
      for (std::size_t i = 0; i < p.size(); ++i) {
        F += p.force[i];
        W += p.mass[i] * g;
        Fabs += norm(p.force[i] - p.mass[i] * g);
        for (std::size_t j = i + 1; j < p.size(); ++j) {
          const double ov = p.radius[i] + p.radius[j] - norm(p.x[i] - p.x[j]);
          if (ov <= 0.0) continue;
          const double Es = kE / (2.0 * (1.0 - kNu * kNu));
          const double rs = p.radius[i] * p.radius[j] / (p.radius[i] + p.radius[j]);
          const double fh = 4.0 / 3.0 * Es * std::sqrt(rs) * std::pow(ov, 1.5);
          pair_bound += ov * mu_s * fh;
          pair_arm += (p.radius[i] + p.radius[j]) * mu_s * fh;
        }
      }
      ASSERT_LT(norm(F - W), 1e-12 * (Fabs + norm(W))) << "step " << k;
      bound += dt * pair_bound;
      arm_scale += dt * pair_arm;
      max_contacts = std::max(max_contacts, sim.interactions().stats().contacts_pp);
    }
    const double t = sim.time();
    const Vec3 dL_ext = M * cross(xc0, g) * t + M * cross(vc0, g) * (0.5 * t * t);
    const double residual = norm(test::angular_momentum(p) - L0 - dL_ext);
    std::printf("[%s] cluster: contacts up to %zu, |dL - dL_ext| = %.3e, bound %.3e, arm scale %.3e N m s\n",
                name(integ), max_contacts, residual, bound, arm_scale);
    EXPECT_GT(max_contacts, 10u);
    EXPECT_LT(residual, 1.5 * bound + 1e-12 * norm(L0));  // 1.5: rectangle-rule quadrature margin
  }
}

// Relabelling: the same cluster with the input order reversed-and-shuffled and new ids ends in
// the same state, matched by id, within 1e-12 relative (positions relative to R, velocities to
// the largest speed, spins to the largest spin).
namespace {

// Largest differences between the states of sphere ids_a[k] in a and ids_b[k] in b: position
// relative to kR, velocity and spin relative to a's largest.
struct StateDifference {
  double x = 0.0, v = 0.0, w = 0.0;
};
StateDifference difference_by_id(const Particles& a, const Particles& b, const std::vector<std::int64_t>& ids_a,
                                 const std::vector<std::int64_t>& ids_b) {
  double vmax = 0.0, wmax = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    vmax = std::max(vmax, norm(a.v[i]));
    wmax = std::max(wmax, norm(a.w[i]));
  }
  StateDifference d;
  for (std::size_t k = 0; k < ids_a.size(); ++k) {
    const std::size_t i = test::index_of(a, ids_a[k]), j = test::index_of(b, ids_b[k]);
    EXPECT_LT(i, a.size());
    EXPECT_LT(j, b.size());
    if (i >= a.size() || j >= b.size()) return {1.0, 1.0, 1.0};
    d.x = std::max(d.x, norm(a.x[i] - b.x[j]) / kR);
    d.v = std::max(d.v, norm(a.v[i] - b.v[j]) / vmax);
    d.w = std::max(d.w, norm(a.w[i] - b.w[j]) / wmax);
  }
  return d;
}

}  // namespace

// The one-material path (constant E*, G*, d_t from d_n's square root) against the general one:
// the frictional, rolling cluster run alone, and again with a distant 19th sphere of another
// material, which touches nothing but makes the kernel take the general path. The 18 spheres'
// states after 800 steps agree to 1e-9 of their scales (the two paths differ only in rounding).
TEST(MixedMaterials, OneMaterialPathEqualsTheGeneralPath) {
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const double dt = 1e-6;
    const int n = 18;
    std::vector<std::int64_t> ids(n);
    std::iota(ids.begin(), ids.end(), 1);
    Scene sa = cluster(integ, dt, identity(n), ids);
    Scene sb = cluster(integ, dt, identity(n), ids);
    const std::size_t far = test::add_particle(sb, 99, kR, {1.0, 1.0, 1.0});
    test::give_own_material(sb, far, 3.0 * kE, 0.25);
    Simulation A(std::move(sa), RunOptions{{}, false, false}), B(std::move(sb), RunOptions{{}, false, false});
    for (int k = 0; k < 800; ++k) {
      A.advance(dt);
      B.advance(dt);
    }
    const std::size_t touching = A.interactions().stats().contacts_pp;
    EXPECT_GT(touching, 10u) << "the cluster must be in contact";
    EXPECT_EQ(B.interactions().stats().contacts_pp, touching);
    const StateDifference d = difference_by_id(A.particles(), B.particles(), ids, ids);
    std::printf("[%s] one-material vs general path: x %.1e, v %.1e, w %.1e\n", name(integ), d.x, d.v, d.w);
    EXPECT_LT(d.x, 1e-9) << name(integ);
    EXPECT_LT(d.v, 1e-9) << name(integ);
    EXPECT_LT(d.w, 1e-9) << name(integ);
  }
}

TEST(Relabelling, FinalStatesMatchById) {
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const double dt = 1e-6;
    const int n = 18;
    std::vector<std::int64_t> ids_a(n), ids_b(n);
    for (int k = 0; k < n; ++k) {
      ids_a[static_cast<std::size_t>(k)] = k + 1;
      ids_b[static_cast<std::size_t>(k)] = 1000 - 37 * k;  // a different id for the same sphere
    }
    std::vector<int> order_b = identity(n);
    std::mt19937 rng(7);
    std::shuffle(order_b.begin(), order_b.end(), rng);
    Scene sa = cluster(integ, dt, identity(n), ids_a);
    Scene sb = cluster(integ, dt, order_b, ids_b);
    Simulation A(std::move(sa), RunOptions{{}, false, false}), B(std::move(sb), RunOptions{{}, false, false});
    for (int k = 0; k < 800; ++k) {
      A.advance(dt);
      B.advance(dt);
    }
    const StateDifference d = difference_by_id(A.particles(), B.particles(), ids_a, ids_b);
    std::printf("[%s] relabelled: max rel diff x %.2e v %.2e w %.2e; contacts %zu\n", name(integ), d.x, d.v, d.w,
                A.interactions().stats().contacts_pp);
    EXPECT_LT(d.x, 1e-12);
    EXPECT_LT(d.v, 1e-12);
    EXPECT_LT(d.w, 1e-12);
  }
}

namespace {

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
  Scene s = base_scene(integ, dt);
  test::set_material(s, kRho, E, kNu);
  s.model.params.contact.particle_particle.damping_ratio = 0.0;  // e = 1
  const double gap = 2.5 * v * dt;
  test::add_particle(s, 1, kR, {-2.0 * kR - gap, 0, 0}, {v, 0, 0});
  for (int k = 0; k < 4; ++k) test::add_particle(s, 2 + k, kR, {2.0 * kR * k, 0, 0});
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  Particles& p = sim.particles();
  auto energy = [&] {
    double K = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) K += 0.5 * p.mass[i] * norm2(p.v[i]) + 0.5 * p.inertia[i] * norm2(p.w[i]);
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
    const double mx = std::accumulate(lx.begin(), lx.end(), 0.0) / n, my = std::accumulate(ly.begin(), ly.end(), 0.0) / n;
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
