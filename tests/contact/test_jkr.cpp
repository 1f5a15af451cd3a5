// JKR adhesion (contact/laws/jkr.hpp), law level, against Johnson, Kendall & Roberts' parametric
// form delta(a) = a^2/r* - sqrt(2 pi w a / E*), F(a) = 4 E* a^3 / (3 r*) - sqrt(8 pi w E* a^3).
// The issue's equal spheres (E = 1e7 Pa, nu = 0.3, R = 1 mm: E* = 5.495 MPa, r* = 0.5 mm) with
// w = 0.05 J/m^2: zero-load overlap 0.674 um at a_0 = 31.80 um, pull-off F_c = 117.8 uN (the
// least force of the branch), break at delta_c = -0.557 um with -65.4 uN = -(5/9) F_c, and the
// energy a loading-unloading cycle dissipates, U(delta_c) = 1.403254 pi w r* |delta_c|.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "contact/contact_law.hpp"
#include "contact/contact_table.hpp"
#include "physics/hertz.hpp"
#include "scene/scene_reader.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kE = 1e7, kNu = 0.3, kR = 1e-3, kW = 0.05;
const double kEStar = kE / (2.0 * (1.0 - kNu * kNu));  // Pa, equal materials (51)
constexpr double kRStar = 0.5 * kR;                    // m, equal spheres (52)
double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

PairLaw jkr_law(double w, double damping = 0.0, double mu = 0.5) {
  ContactLawParams p;
  p.cohesion = "jkr";
  p.law_keys["surface_energy"] = w;
  p.damping_ratio = damping;
  p.mu_static = p.mu_dynamic = mu;
  return resolve_pair_law(p, kEStar, 0.4 * kEStar);
}

// JKR's parametric form, straight from the paper.
double jkr_overlap(double a, double w) { return a * a / kRStar - std::sqrt(2.0 * kPi * w * a / kEStar); }
double jkr_force(double a, double w) {
  return 4.0 * kEStar * a * a * a / (3.0 * kRStar) - std::sqrt(8.0 * kPi * w * kEStar * a * a * a);
}

// The acceptance numbers, and the solver at the zero-load point: from delta_0 it finds a_0
// (k_n = 2 E* a) and F = 0, both to 1e-10 (of a_0, of F_c).
TEST(JkrLaw, ZeroLoadPointAndTheIssuesNumbers) {
  EXPECT_NEAR(kEStar, 5.495e6, 1e3);
  const double a0 = jkr_zero_load_radius(kW, kRStar, kEStar), d0 = jkr_zero_load_overlap(kW, kRStar, kEStar);
  const double fc = jkr_pull_off_force(kW, kRStar);
  std::printf("a_0 = %.6g um, delta_0 = %.6g um, F_c = %.6g uN\n", 1e6 * a0, 1e6 * d0, 1e6 * fc);
  EXPECT_NEAR(1e6 * a0, 31.80, 0.005);
  EXPECT_NEAR(1e6 * d0, 0.674, 0.0005);
  EXPECT_NEAR(1e6 * fc, 117.8, 0.05);
  EXPECT_LT(std::abs(jkr_overlap(a0, kW) - d0), 1e-13 * d0);  // the closed forms are JKR's
  EXPECT_LT(std::abs(jkr_force(a0, kW)), 1e-12 * fc);
  const PairLaw law = jkr_law(kW);
  const Stiffness s = JkrLaw::stiffness(law, kRStar, d0);
  EXPECT_LT(std::abs(s.f_el), 1e-10 * fc);
  EXPECT_LT(rel(s.k_n / (2.0 * kEStar), a0), 1e-10);
  EXPECT_LT(rel(s.k_t / (8.0 * 0.4 * kEStar), a0), 1e-10);
  EXPECT_EQ(s.adhesion, fc);
  EXPECT_EQ(s.load_offset, 2.0 * fc);
}

// The pull-off F_c = 1.5 pi w r* is the least force of the branch: a golden-section search over
// [delta_c, delta_0] finds it to 1e-6.
TEST(JkrLaw, PullOffIsTheLeastForceOfTheBranch) {
  const PairLaw law = jkr_law(kW);
  const auto force = [&](double d) { return JkrLaw::stiffness(law, kRStar, d).f_el; };
  double lo = JkrLaw::break_overlap(law, kRStar), hi = jkr_zero_load_overlap(kW, kRStar, kEStar);
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = force(x1), f2 = force(x2);
  for (int k = 0; k < 200 && hi - lo > 1e-15; ++k) {
    if (f1 < f2) hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo), f1 = force(x1);
    else lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo), f2 = force(x2);
  }
  const double least = std::min(f1, f2), fc = jkr_pull_off_force(kW, kRStar);
  std::printf("least force %.10g uN at %.6g um (-1.5 pi w r* = %.10g uN)\n", 1e6 * least, 1e6 * x1, -1e6 * fc);
  EXPECT_LT(rel(-least, fc), 1e-6);
  EXPECT_NEAR(-1e6 * least, 117.8, 0.05);
}

// The break: delta_c = -(3/4) (pi^2 w^2 r* / E*^2)^(1/3) = -0.557 um with F = -(5/9) F_c =
// -65.4 uN. At delta_c itself F ~ sqrt(delta - delta_c) turns delta_c's rounding into 1e-8 of
// F (1e-7 asked); just below it the branch's end is exact (1e-12).
TEST(JkrLaw, BreakOverlapAndForce) {
  const PairLaw law = jkr_law(kW);
  const double dc = JkrLaw::break_overlap(law, kRStar), fc = jkr_pull_off_force(kW, kRStar);
  EXPECT_LT(rel(dc, jkr_break_overlap(kW, kRStar, kEStar)), 1e-14);
  EXPECT_NEAR(1e6 * dc, -0.557, 0.0005);
  // The fold of JKR's parametric form: a_c = a_0 / 6^(2/3), d(delta)/da = 0 there.
  const double ac = jkr_zero_load_radius(kW, kRStar, kEStar) / std::cbrt(36.0);
  EXPECT_LT(rel(jkr_overlap(ac, kW), dc), 1e-13);
  EXPECT_LT(rel(jkr_force(ac, kW), -5.0 / 9.0 * fc), 1e-13);
  EXPECT_EQ(jkr_break_force(kW, kRStar), -5.0 / 9.0 * fc);
  const Stiffness at = JkrLaw::stiffness(law, kRStar, dc);
  std::printf("delta_c = %.6g um, F(delta_c) = %.6g uN\n", 1e6 * dc, 1e6 * at.f_el);
  EXPECT_LT(rel(at.f_el, -5.0 / 9.0 * fc), 1e-7);
  EXPECT_NEAR(1e6 * at.f_el, -65.4, 0.05);
  for (const double below : {dc - 1e-12, dc - 1e-9, 10.0 * dc}) {
    const Stiffness s = JkrLaw::stiffness(law, kRStar, below);
    EXPECT_LT(rel(s.f_el, -5.0 / 9.0 * fc), 1e-12) << below;
    EXPECT_LT(rel(s.k_n, 2.0 * kEStar * ac), 1e-12) << below;
  }
}

// The solver over the branch, from just above the fold to delta = 1e-2 r*: a sampled along JKR's
// parametric form, the law's force at delta(a) equals F(a) to 1e-12 of max(|F|, F_c) and its
// stiffness is 2 E* a to 1e-12.
TEST(JkrLaw, ForceAlongTheBranchIsJkrs) {
  for (const double w : {kW, 1e-4, 5.0}) {
    const PairLaw law = jkr_law(w);
    const double ac = jkr_zero_load_radius(w, kRStar, kEStar) / std::cbrt(36.0), fc = jkr_pull_off_force(w, kRStar);
    const double top = std::sqrt(kRStar * 1.1e-2 * kRStar) + 2.0 * ac;  // delta(top) > 1e-2 r*
    double worst_f = 0.0, worst_k = 0.0;
    int n = 0;
    for (double a = ac * (1.0 + 1e-3); a < top; a *= 1.01, ++n) {
      const double d = jkr_overlap(a, w), f = jkr_force(a, w);
      const Stiffness s = JkrLaw::stiffness(law, kRStar, d);
      worst_f = std::max(worst_f, std::abs(s.f_el - f) / std::max(std::abs(f), fc));
      worst_k = std::max(worst_k, rel(s.k_n, 2.0 * kEStar * a));
    }
    std::printf("w = %g: %d points, force error %.3g, stiffness error %.3g\n", w, n, worst_f, worst_k);
    EXPECT_GT(n, 100);
    EXPECT_LT(worst_f, 1e-12) << w;
    EXPECT_LT(worst_k, 1e-12) << w;
  }
}

// w = 0 is the Hertz law to 1e-12: force, energy and both stiffnesses; nothing at touching.
TEST(JkrLaw, ZeroSurfaceEnergyIsHertz) {
  const PairLaw jkr = jkr_law(0.0);
  ContactLawParams p;
  p.mu_static = p.mu_dynamic = 0.5;
  const PairLaw hertz = resolve_pair_law(p, kEStar, 0.4 * kEStar);
  for (const double d : {1e-12, 1e-9, 1e-7, 1e-6, 1e-5, 1e-4, 5e-6}) {
    const Stiffness a = JkrLaw::stiffness(jkr, kRStar, d), b = HertzLaw::stiffness(hertz, kRStar, d);
    EXPECT_LT(rel(a.f_el, b.f_el), 1e-12) << d;
    EXPECT_LT(rel(a.energy, b.energy), 1e-12) << d;
    EXPECT_LT(rel(a.k_n, b.k_n), 1e-12) << d;
    EXPECT_LT(rel(a.k_t, b.k_t), 1e-12) << d;
    EXPECT_EQ(a.adhesion, 0.0);
  }
  const Stiffness zero = JkrLaw::stiffness(jkr, kRStar, 0.0);
  EXPECT_EQ(zero.f_el, 0.0);
  EXPECT_EQ(zero.energy, 0.0);
  EXPECT_EQ(zero.k_n, 0.0);
  EXPECT_EQ(JkrLaw::break_overlap(jkr, kRStar), 0.0);
}

// The energy is the integral of the force along the branch: zero at touching, its central
// difference equal to F to 1e-6 of max(|F|, F_c), and at delta_c the cycle's closed form.
TEST(JkrLaw, EnergyIsTheIntegralOfTheForce) {
  const PairLaw law = jkr_law(kW);
  const double dc = JkrLaw::break_overlap(law, kRStar), fc = jkr_pull_off_force(kW, kRStar);
  const double cycle = jkr_cycle_energy(kW, kRStar, kEStar);
  EXPECT_LT(std::abs(JkrLaw::stiffness(law, kRStar, 0.0).energy), 1e-12 * fc * -dc);
  for (const double d : {0.9 * dc, 0.5 * dc, 0.1 * dc, 1e-8, 1e-7, 6.74e-7, 1e-6, 1e-5, 1e-4}) {
    const double h = 1e-4 * std::abs(d);
    const double slope = (JkrLaw::stiffness(law, kRStar, d + h).energy - JkrLaw::stiffness(law, kRStar, d - h).energy) /
                         (2.0 * h);
    const double f = JkrLaw::stiffness(law, kRStar, d).f_el;
    EXPECT_LT(std::abs(slope - f), 1e-6 * std::max(std::abs(f), fc)) << d;
  }
  const double at_break = JkrLaw::stiffness(law, kRStar, dc).energy;
  std::printf("U(delta_c) = %.10g J, cycle closed form %.10g J = %.7f pi w r* |delta_c|\n", at_break, cycle,
              cycle / (kPi * kW * kRStar * -dc));
  EXPECT_GT(at_break, 0.0);
  EXPECT_LT(rel(at_break, cycle), 1e-10);
  // The same constant in the other closed form, 7.092196 (w^5 r*^4 / E*^2)^(1/3).
  EXPECT_LT(rel(cycle, 7.092195972 * std::cbrt(std::pow(kW, 5) * std::pow(kRStar, 4) / (kEStar * kEStar))), 1e-9);
}

// The cycle energy against a numerical integral of the law's force from delta_c to 0: with
// delta = delta_c + t^2 the integrand F 2t is smooth in t (F ~ sqrt(delta - delta_c) at the
// fold); composite Simpson, 4000 intervals, agrees to 1e-8.
TEST(JkrLaw, CycleEnergyIsTheWorkOfTheBranch) {
  const PairLaw law = jkr_law(kW);
  const double dc = JkrLaw::break_overlap(law, kRStar), span = std::sqrt(-dc);
  const int n = 4000;
  const double h = span / n;
  double sum = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double t = k * h;
    const double f = JkrLaw::stiffness(law, kRStar, k == n ? 0.0 : dc + t * t).f_el * 2.0 * t;
    sum += (k == 0 || k == n ? 1.0 : k % 2 == 1 ? 4.0 : 2.0) * f;
  }
  const double work = -sum * h / 3.0;  // J, -integral of F from delta_c to 0 = U(delta_c)
  const double cycle = jkr_cycle_energy(kW, kRStar, kEStar);
  std::printf("cycle: numerical %.12g J, closed form %.12g J\n", work, cycle);
  EXPECT_LT(rel(work, cycle), 1e-8);
}

// With damping, over the whole branch and past its end (delta_c - 1e-9 to 1e-4) and rates of
// +-1 m/s: everything finite, k_n finite and > 0, the net force never below -F_c, Coulomb's load
// f_n + 2 F_c >= F_c.
TEST(JkrLaw, DashpotIsFiniteOverTheBranch) {
  const PairLaw law = jkr_law(kW, 0.5, 0.3);
  const double dc = JkrLaw::break_overlap(law, kRStar), fc = jkr_pull_off_force(kW, kRStar);
  const double m = 2500.0 * 4.0 / 3.0 * kPi * kR * kR * kR;  // kg, one sphere
  std::vector<double> overlaps;
  for (int k = 0; k <= 1000; ++k) overlaps.push_back(dc - 1e-9 + k * (1e-9 - dc) / 1000.0);
  for (double d = 1e-12; d <= 1e-4; d *= 1.2) overlaps.push_back(d);
  int n = 0;
  for (const double d : overlaps)
    for (const double rate : {-1.0, -1e-3, 0.0, 1e-3, 1.0}) {
      const Stiffness s = JkrLaw::stiffness(law, kRStar, d);
      ASSERT_TRUE(std::isfinite(s.k_n) && s.k_n > 0.0) << d;
      ContactState c;
      c.overlap = d, c.r_star = kRStar, c.m_star = 0.5 * m, c.normal = {0, 0, 1};
      c.normal_rate = rate, c.vt = {0.01, 0.0, 0.0}, c.increment = {1e-9, 0.0, 0.0};
      const ContactResult r = evaluate_contact<JkrLaw>(law, c);
      ASSERT_TRUE(std::isfinite(r.fn) && std::isfinite(r.fn_limit) && std::isfinite(r.ft.x) &&
                  std::isfinite(r.energy) && std::isfinite(r.damping))
          << d << " " << rate;
      EXPECT_GE(r.fn, -fc) << d << " " << rate;
      EXPECT_GE(r.fn_limit, fc * (1.0 - 1e-15)) << d << " " << rate;
      ++n;
    }
  EXPECT_GT(n, 5000);
}

// Receding fast, the dashpot would pull harder than the pull-off: the force stops at -F_c and
// Coulomb's load is F + 2 F_c = F_c (Thornton & Yin); a sliding contact's tangential force is
// mu_d times that load.
TEST(JkrLaw, ClampAtThePullOffAndThorntonsSlidingLimit) {
  const PairLaw law = jkr_law(kW, 0.5, 0.3);
  const double fc = jkr_pull_off_force(kW, kRStar);
  ContactState c;
  c.overlap = 1e-7, c.r_star = kRStar, c.m_star = 1e-5, c.normal = {0, 0, 1};
  c.normal_rate = 10.0;  // m/s, receding
  const ContactResult fast = evaluate_contact<JkrLaw>(law, c);
  EXPECT_EQ(fast.fn, -fc);
  EXPECT_EQ(fast.fn_limit, fc);
  c.normal_rate = 0.0;
  c.increment = {1e-3, 0.0, 0.0};  // far beyond the stick limit
  const ContactResult slide = evaluate_contact<JkrLaw>(law, c);
  EXPECT_TRUE(slide.slipped);
  EXPECT_LT(slide.fn, 0.0);
  EXPECT_LT(rel(slide.fn_limit, slide.fn + 2.0 * fc), 1e-12);
  EXPECT_LT(rel(-slide.ft.x, 0.3 * slide.fn_limit), 1e-12);
}

// The scene keys: cohesion = "jkr" with surface_energy (the key DMT has too) under [contact.*]
// and [[contact.pair]]; a negative w is refused.
TEST(JkrLaw, SceneKeys) {
  const std::string head = "[time]\nduration = 1.0\ndt = 1e-5\n"
                           "[[material]]\nname = \"glass\"\n[[material]]\nname = \"steel\"\n";  // lines 1-7
  test::TempDir d("mpdem_jkr");
  const auto scene = d.write("scene.toml", head + "[contact.particle_particle]\ncohesion = \"jkr\"\n"
                                                  "surface_energy = 0.05\n"
                                                  "[[contact.pair]]\nmaterials = [\"glass\", \"steel\"]\n"
                                                  "cohesion = \"dmt\"\nsurface_energy = 0.2\n");
  const Scene s = parse_scene_file(scene);
  ContactTable t;
  t.build(s.model);
  EXPECT_EQ(t.particle_pair(0, 0).law, law_id<JkrLaw>());
  EXPECT_EQ(t.particle_pair(0, 0).c[JkrLaw::kPullOff], 1.5 * kPi * 0.05);
  EXPECT_EQ(t.particle_pair(0, 1).law, law_id<DmtLaw>());
  EXPECT_EQ(t.particle_pair(0, 1).c[DmtLaw::kTwoPiW], 2.0 * kPi * 0.2);
  const auto bad = d.write("bad.toml", head + "[contact.particle_barrier]\ncohesion = \"jkr\"\nsurface_energy = -1\n");
  const std::string msg = test::error_of([&] { parse_scene_file(bad); });
  test::expect_contains(msg,
                        {bad.string() + ":10: 'contact.particle_barrier.surface_energy': ", "expected a number >= 0"});
}

}  // namespace
