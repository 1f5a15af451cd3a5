#pragma once
// Johnson-Kendall-Roberts adhesion (Johnson, Kendall & Roberts 1971, Proc. R. Soc. Lond. A 324,
// 301): law = "hertz", cohesion = "jkr" (docs/physics.md section 15). With the contact radius a,
//   delta = a^2 / r* - sqrt(2 pi w a / E*),   F = 4 E* a^3 / (3 r*) - sqrt(8 pi w E* a^3),
// w the surface energy (J/m^2). The contact forms when the surfaces touch (delta = 0, where it
// snaps to a > 0 and F = -8/9 F_c) and holds on the stable branch down to the overlap delta_c < 0
// where d(delta)/da = 0 (the neck), then breaks (kHysteresis).
// Solving a(delta): with x = sqrt(a), c = r* sqrt(2 pi w / E*) and x_c^3 = c / 4 (the fold),
//   x^4 - c x = r* delta   <=>   y^2 (y^2 + 4 x_c y + 6 x_c^2) = r* (delta - delta_c),  y = x - x_c,
// so the stable branch is the root y >= 0 of y sqrt(y^2 + 4 x_c y + 6 x_c^2) = S = sqrt(r* (delta -
// delta_c)): increasing and convex, a simple root even at the fold (where a(delta) itself has an
// infinite slope), found by three Newton steps from a start within 0.33 % (2e-16 after three).
// w = 0 gives x_c = 0, the start y = sqrt(S) = (r* delta)^(1/4), exact: the Hertz law.
// - k_n = 2 E* a, the flat-punch stiffness of the contact radius: finite and > 0 on the whole
//   branch (dF/d(delta) diverges at delta_c), for the dashpot and the time step; k_t = 8 G* a.
// - Clamp: the net force, dashpot included, is never more attractive than the pull-off -F_c.
// - Coulomb's limit and rolling resistance scale with F + 2 F_c (Thornton & Yin 1991, Powder
//   Technol. 65, 153): friction acts on the contact's compressive (Hertzian) pressure, whose load
//   P_1 = 4 E* a^3 / (3 r*) is F + 2 F_c +- 2 sqrt(F_c (F + F_c)) on the two parts of the branch;
//   F + 2 F_c is their mean, exact at the pull-off, > 0 on the whole branch (F >= -F_c), F
//   without adhesion, and needs no root.
// - Energy: the integral of F along the branch from touching, in closed form in x; 0 at delta = 0,
//   > 0 at delta_c, where the break loses it (the kernels book it as dissipated).
// - Below delta_c (a step past the break) S is clamped at 0: the branch's end, never NaN.
#include <cmath>
#include <numbers>

#include "contact/laws/hertz.hpp"
#include "contact/laws/law_interface.hpp"
#include "physics/restitution.hpp"

namespace mpdem {

// Closed forms of the JKR contact (w: J/m^2, r: effective radius r* in m, E: E* in Pa).
// N, the pull-off force F_c: the least force of the branch (load-controlled separation).
inline double jkr_pull_off_force(double w, double r) { return 1.5 * std::numbers::pi * w * r; }
// m, the contact radius at zero load, a_0 = (9 pi w r*^2 / (2 E*))^(1/3).
inline double jkr_zero_load_radius(double w, double r, double E) {
  return std::cbrt(4.5 * std::numbers::pi * w * r * r / E);
}
// m, the overlap at zero load, a_0^2 / (3 r*).
inline double jkr_zero_load_overlap(double w, double r, double E) {
  const double a0 = jkr_zero_load_radius(w, r, E);
  return a0 * a0 / (3.0 * r);
}
// m, <= 0: the overlap at which the contact breaks (displacement-controlled separation),
// delta_c = -(3/4) (pi^2 w^2 r* / E*^2)^(1/3), at the contact radius a_c = a_0 / 6^(2/3).
inline double jkr_break_overlap(double w, double r, double E) {
  const double pi = std::numbers::pi;
  return -0.75 * std::cbrt(pi * pi * w * w * r / (E * E));
}
// N, the force at delta_c: -(5/9) F_c.
inline double jkr_break_force(double w, double r) { return -5.0 / 9.0 * jkr_pull_off_force(w, r); }
// J, the energy a quasi-static displacement-controlled loading-unloading cycle dissipates: the
// snap-in at delta = 0 does no work, the branch is reversible, the jump to zero at delta_c loses
// U(delta_c) = (2/15 + 4/5 2^(2/3)) pi w r* |delta_c| = 1.403254 pi w r* |delta_c|
// (= 7.092196 (w^5 r*^4 / E*^2)^(1/3)).
inline double jkr_cycle_energy(double w, double r, double E) {
  return (2.0 / 15.0 + 0.8 * std::cbrt(4.0)) * std::numbers::pi * w * r * -jkr_break_overlap(w, r, E);
}

struct JkrLaw : HertzEstimates {  // the Hertz impact estimates
  static constexpr std::string_view kLaw = "hertz", kCohesion = "jkr";
  static constexpr std::array<LawKey, 1> kKeys{{
      {"surface_energy", "J/m^2", kNonNegative, 0.0, false, "0", "surface energy w: pull-off 1.5 pi w r*"},
  }};
  static constexpr std::size_t kTwiceE = HertzLaw::kTwiceE;  // Pa, 2 E*: k_n = 2 E* a
  static constexpr std::size_t kEightG = HertzLaw::kEightG;  // Pa, 8 G*: k_t = 8 G* a
  static constexpr std::size_t kBeta = kLawSlots + 2;        // m^(1/2), sqrt(2 pi w / E*): c = r* kBeta
  static constexpr std::size_t kPullOff = kLawSlots + 3;     // N/m, 1.5 pi w: F_c = kPullOff r*
  static constexpr std::size_t kEnd = kLawSlots + 4;
  static constexpr bool kElastic = true, kAdhesion = true;
  static constexpr bool kHysteresis = true;
  static constexpr bool kExactGeometry = false;

  static auto coefficients(const LawInputs& in) {
    const double w = in.key(kKeys[0]).value_or(0.0);
    return law_slots<JkrLaw>(2.0 * in.E_star, 8.0 * in.G_star, std::sqrt(2.0 * std::numbers::pi * w / in.E_star),
                             1.5 * std::numbers::pi * w);
  }
  static double damping_ratio(double e) { return damping_ratio_for_restitution(e); }

  // m^(1/2), x_c = sqrt(a_c): x_c^3 = r* sqrt(2 pi w / E*) / 4.
  template <class Pair>
  static double fold_root(const Pair& law, double r_star) {
    return std::cbrt(0.25 * r_star * law.c[kBeta]);
  }
  // m, <= 0: delta_c = -3 x_c^4 / r*.
  template <class Pair>
  static double break_overlap(const Pair& law, double r_star) {
    const double xc = fold_root(law, r_star), xc2 = xc * xc;
    return -3.0 * xc2 * xc2 / r_star;
  }

  template <class Pair>
  static Stiffness stiffness(const Pair& law, double r_star, double overlap, double /*inv_reach*/ = 0.0) {
    constexpr double kStart = (2.449489742783178 - 1.0) * (2.449489742783178 - 1.0);  // (sqrt(6) - 1)^2
    constexpr double kCbrtFour = 1.5874010519681994;                                  // 4^(1/3)
    constexpr double kTiny = 1e-300;                       // keeps 0/0 at w = 0, delta = 0 finite
    const double c = r_star * law.c[kBeta];                // m^(3/2)
    const double xc = std::cbrt(0.25 * c), xc2 = xc * xc;  // m^(1/2), m
    const double s2 = r_star * overlap + 3.0 * xc2 * xc2;  // m^2, r* (delta - delta_c)
    const double S = std::sqrt(s2 > 0.0 ? s2 : 0.0);       // m
    // The start: exact for small S (y = S / (sqrt(6) x_c)) and large S (y = sqrt(S) - x_c).
    const double first = std::sqrt(S + kStart * xc2) + xc;
    double y = S / (first > kTiny ? first : kTiny);  // m^(1/2)
    for (int k = 0; k < 3; ++k) {
      const double h = y * y + 4.0 * xc * y + 6.0 * xc2;  // m
      const double root = std::sqrt(h);
      const double slope = 2.0 * h + y * (2.0 * y + 4.0 * xc);  // 2 root d(y root)/dy
      y -= (y * root - S) * 2.0 * root / (slope > kTiny ? slope : kTiny);
    }
    const double x = xc + y, a = x * x, x3 = a * x;  // m^(1/2), m, m^(3/2)
    Stiffness s;
    s.k_n = law.c[kTwiceE] * a;
    s.k_t = law.c[kEightG] * a;
    const double e_over_r = law.c[kTwiceE] / r_star;  // Pa/m, 2 E* / r*
    s.f_el = e_over_r * x3 * ((2.0 / 3.0) * x3 - c);
    // 2 E* / r*^2 (4/15 x^10 - 2/3 c x^7 + 1/4 c^2 x^4 + 3/20 c^(10/3)), c^(1/3) = 4^(1/3) x_c.
    const double xc10 = xc2 * xc2 * xc2 * xc2 * xc2;
    const double a2 = a * a;
    s.energy = e_over_r / r_star *
               (a2 * ((4.0 / 15.0) * a2 * a - (2.0 / 3.0) * c * x3 + 0.25 * c * c) + 9.6 * kCbrtFour * xc10);
    s.adhesion = law.c[kPullOff] * r_star;
    s.load_offset = 2.0 * s.adhesion;
    return s;
  }
};

}  // namespace mpdem
