// The tangential law (stick-slip, spring projection, third law) and the rolling-resistance limiter
// (physics.md sections 6-7). Every tolerance is stated where it is used.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/vec3.hpp"
#include "physics/rolling.hpp"
#include "physics/tangential.hpp"
#include "support/hertz_oracle.hpp"

using namespace mpdem;

// ---------------------------------------------------------------------------------------------
// Tangential law
// ---------------------------------------------------------------------------------------------

TEST(Tangential, EffectiveShearModulus) {
  // Identical materials: 1/G* = 2 (2 - nu)/G; rigid partner: G/(2 - nu) (section 7); 1e-12 rel.
  const double G = shear_modulus(2.1e11, 0.3);
  EXPECT_NEAR(G, 2.1e11 / 2.6, 1e-12 * G);
  EXPECT_NEAR(effective_shear_modulus(G, 0.3, G, 0.3), G / (2 * 1.7), 1e-12 * G);
  EXPECT_NEAR(effective_shear_modulus(G, 0.3, 1e30, 0.2), effective_shear_modulus_rigid(G, 0.3), 1e-12 * G);
  EXPECT_NEAR(effective_shear_modulus_rigid(G, 0.3), G / 1.7, 1e-12 * G);
  // (65), (67); 1e-12 rel.
  const double kt = tangential_stiffness(1e9, 0.01, 1e-6);
  EXPECT_NEAR(kt, 8e9 * 1e-4, 1e-12 * kt);
  EXPECT_NEAR(tangential_damping_coefficient(0.2, 0.5, kt), 0.4 * std::sqrt(0.5 * kt), 1e-12 * kt);
}

TEST(Tangential, SticksBelowStaticLimit) {
  const Vec3 s{1e-6, 0, 0}, ds{0, 2e-7, 0}, vt{0, 0.01, 0};
  const double kt = 1e6, dt_ = 5.0, fn = 10.0;
  // Trial force -(kt (s+ds) + d vt) = (-1, -0.25, 0): |f| = 1.03 < mu_s fn = 2, > mu_d fn = 1.
  const TangentialResult r = tangential_force(s, ds, vt, kt, dt_, 0.2, 0.1, fn);
  EXPECT_FALSE(r.slipped);
  EXPECT_NEAR(r.force.x, -1.0, 1e-12);
  EXPECT_NEAR(r.force.y, -0.25, 1e-12);
  EXPECT_NEAR(r.force.z, 0.0, 1e-12);
  EXPECT_NEAR(norm(r.spring - (s + ds)), 0.0, 1e-18);
  EXPECT_NEAR(r.dissipated_power, dt_ * 1e-4, 1e-15);
  // Exactly at the static limit still sticks (68 uses <=).
  const TangentialResult edge = tangential_force({0.125, 0, 0}, {}, {}, 8.0, 0.0, 0.5, 0.25, 2.0);
  EXPECT_FALSE(edge.slipped);
}

TEST(Tangential, SlipsAtDynamicLimitOpposingTrialDeformation) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    const Vec3 s{u(rng) * 1e-4, u(rng) * 1e-4, 0}, ds{u(rng) * 1e-5, u(rng) * 1e-5, 0};
    const Vec3 vt{u(rng), u(rng), 0};
    const double kt = 1e6, d = 50.0, fn = 10.0, mus = 0.5, mud = 0.3;
    const Vec3 trial = -(kt * (s + ds) + d * vt);
    if (norm(trial) <= mus * fn * 1.001) continue;  // these cases must slip
    const TangentialResult r = tangential_force(s, ds, vt, kt, d, mus, mud, fn);
    ASSERT_TRUE(r.slipped);
    // |f_t| = mu_d |f_n|, along the trial force, i.e. opposing kt s_tent + d vt; 1e-12 rel.
    EXPECT_NEAR(norm(r.force), mud * fn, 1e-12 * mud * fn);
    EXPECT_NEAR(dot(r.force, trial) / (norm(r.force) * norm(trial)), 1.0, 1e-12);
    // Stored spring at the dynamic limit, k_t |s| = mu_d |f_n|, so that -k_t s = f_t.
    EXPECT_NEAR(kt * norm(r.spring), mud * fn, 1e-12 * mud * fn);
    EXPECT_NEAR(norm(-kt * r.spring - r.force), 0.0, 1e-12 * mud * fn);
    EXPECT_NEAR(r.dissipated_power, -dot(r.force, vt), 1e-12);
  }
  // Pure sliding from a fresh contact: the force opposes the sliding velocity.
  const Vec3 vt{0.3, -0.4, 0};
  const TangentialResult r = tangential_force({}, vt * 1e-3, vt, 1e6, 0.0, 0.5, 0.4, 2.0);
  ASSERT_TRUE(r.slipped);
  EXPECT_NEAR(dot(r.force, vt) / (norm(r.force) * norm(vt)), -1.0, 1e-12);
  EXPECT_NEAR(r.dissipated_power, 0.8 * 0.5, 1e-12);  // mu_d f_n |v_t|
}

TEST(Tangential, ProjectionKeepsLengthAndRemovesNormalPart) {
  std::mt19937 rng(11);
  std::normal_distribution<double> g(0.0, 1.0);
  for (int k = 0; k < 1000; ++k) {
    const Vec3 s{g(rng) * 1e-5, g(rng) * 1e-5, g(rng) * 1e-5};
    Vec3 n{g(rng), g(rng), g(rng)};
    n = n / norm(n);
    const Vec3 p = project_spring(s, n);
    EXPECT_NEAR(norm(p) / norm(s), 1.0, 1e-12);    // length kept, 1e-12 rel
    EXPECT_NEAR(dot(p, n), 0.0, 1e-12 * norm(s));  // in the tangent plane
    EXPECT_GT(dot(p, s), 0.0);                     // same side as before
  }
  EXPECT_EQ(norm(project_spring({0, 0, 2e-6}, {0, 0, 1})), 0.0);  // no tangential direction
  EXPECT_EQ(norm(project_spring({}, {0, 0, 1})), 0.0);
}

TEST(Tangential, NewtonsThirdLaw) {
  // Seen from j, every relative quantity flips sign (spring, increment, velocity): the force on
  // j must be exactly minus the force on i, in stick and in slip.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int slips = 0, sticks = 0;
  for (int k = 0; k < 500; ++k) {
    const Vec3 s{u(rng) * 1e-5, u(rng) * 1e-5, u(rng) * 1e-5}, ds{u(rng) * 1e-6, 0, u(rng) * 1e-6};
    const Vec3 vt{u(rng) * 0.1, u(rng) * 0.1, 0};
    const double fn = 5.0 * (1.0 + u(rng));
    const TangentialResult ri = tangential_force(s, ds, vt, 1e6, 30.0, 0.6, 0.5, fn);
    const TangentialResult rj = tangential_force(-s, -ds, -vt, 1e6, 30.0, 0.6, 0.5, fn);
    EXPECT_NEAR(norm(ri.force + rj.force), 0.0, 1e-12 * (1.0 + norm(ri.force)));
    EXPECT_NEAR(norm(ri.spring + rj.spring), 0.0, 1e-18);
    EXPECT_EQ(ri.slipped, rj.slipped);
    (ri.slipped ? slips : sticks)++;
  }
  EXPECT_GT(slips, 0);  // both branches were exercised
  EXPECT_GT(sticks, 0);
}

// ---------------------------------------------------------------------------------------------
// Rolling resistance
// ---------------------------------------------------------------------------------------------

TEST(Rolling, OpposesRelativeRotationAndFollows71WhenUnlimited) {
  const Vec3 w{0.0, 3.0, -4.0};
  // Large inertia, small dt: limiter inactive, |T| = mu_r r* |f_n|; 1e-12 rel.
  const Vec3 T = rolling_resistance_torque(w, 0.1, 0.02, 50.0, 1.0, 1e-6);
  EXPECT_NEAR(norm(T), 0.1 * 0.02 * 50.0, 1e-12 * 0.1);
  EXPECT_NEAR(dot(T, w) / (norm(T) * norm(w)), -1.0, 1e-12);
  // Limiter active: |T| = |w| I_eff / dt; 1e-12 rel.
  const Vec3 L = rolling_resistance_torque(w, 0.1, 0.02, 50.0, 1e-8, 1e-3);
  EXPECT_NEAR(norm(L), 5.0 * 1e-8 / 1e-3, 1e-12 * 5e-5);
  EXPECT_EQ(norm(rolling_resistance_torque({}, 0.1, 0.02, 50.0, 1.0, 1e-3)), 0.0);
  EXPECT_NEAR(rolling_inertia_pair(2.0, 2.0), 1.0, 1e-15);
}

TEST(Rolling, LimiterNeverReversesRelativeRotationInOneExplicitStep) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto logu = [&](double lo, double hi) { return std::pow(10.0, lo + (hi - lo) * 0.5 * (1 + u(rng))); };
  int limited = 0;
  for (int k = 0; k < 1000; ++k) {
    const bool barrier = k % 4 == 0;
    const Vec3 wi{u(rng) * 50, u(rng) * 50, u(rng) * 50};
    const Vec3 wj = barrier ? Vec3{} : Vec3{u(rng) * 50, u(rng) * 50, u(rng) * 50};
    const double Ii = logu(-12, -3), Ij = logu(-12, -3);
    const double Ieff = barrier ? Ii : rolling_inertia_pair(Ii, Ij);
    const double dt = logu(-7, -2), fn = logu(-3, 4), mur = logu(-3, 0), rs = logu(-4, -1);
    const Vec3 T = rolling_resistance_torque(wi - wj, mur, rs, fn, Ieff, dt);
    if (norm(T) < 0.999999 * mur * rs * fn) ++limited;
    // Explicit step: i gets T, j gets -T (a barrier does not rotate).
    const Vec3 wi1 = wi + T * (dt / Ii);
    const Vec3 wj1 = barrier ? wj : wj - T * (dt / Ij);
    const Vec3 w0 = wi - wj, w1 = wi1 - wj1;
    // Never reversed (component along the old w_rel stays >= 0) and never sped up; 1e-9 rel
    // allows for rounding when the limiter stops the rotation exactly.
    EXPECT_GE(dot(w1, w0), -1e-9 * norm2(w0)) << k;
    EXPECT_LE(norm(w1), norm(w0) * (1 + 1e-12)) << k;
  }
  EXPECT_GT(limited, 100);  // the limiter was actually exercised
}
