// Particle-particle contact balance and invariance through the whole engine (physics.md sections 5, 6): Newton's
// third law and torque arms (62), a frictional cluster's force and angular-momentum balance, kernel paths, relabelling.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <random>
#include <vector>

#include "sim/simulation.hpp"
#include "support/barrier_mechanics_scene.hpp"
#include "support/contact_scenes.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;
using namespace mpdem::test;  // kR, kE, kNu, name, base_scene

namespace {

// Two spheres in an oblique, spinning, frictional contact (no gravity).
Scene oblique_pair(Integrator integ, double dt, double mu_r) {
  Scene s = base_scene(integ, dt, {});  // no gravity
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

// A compressed frictional cluster: 3 x 3 x 2 spheres of alternating radii on a lattice closer
// than touching, random velocities and spins, gravity g. `perm` relabels: input position k holds
// particle perm[k], whose id is 100 + 7 * perm[k]... (ids are permuted too).
Scene cluster(Integrator integ, double dt, const std::vector<int>& order, const std::vector<std::int64_t>& ids) {
  Scene s = base_scene(integ, dt, {});
  s.model.params.fields.gravity = {0.5, -1.0, -9.81};
  ContactLawParams& c = s.model.params.contact.particle_particle;
  c.damping_ratio = 0.0;  // elastic normal law: f_n is the Hertz force (bound below)
  c.mu_static = 0.4;
  c.mu_dynamic = 0.3;
  c.mu_rolling = 0.05;
  c.tangential_damping = 0.3;
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  struct Init {
    double R;
    Vec3 x, v, w;
  };
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

// Relabelling: the same cluster with the input order reversed-and-shuffled and new ids ends in
// the same state, matched by id, within 1e-12 relative (positions relative to R, velocities to
// the largest speed, spins to the largest spin).
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
