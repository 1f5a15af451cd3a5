#pragma once
// Linear spring-dashpot with a Coulomb-capped tangential spring (Cundall-Strack; physics.md
// section 13): law = "linear", no cohesion.
#include <cmath>

#include "contact/laws/law_interface.hpp"
#include "physics/hertz.hpp"
#include "physics/restitution.hpp"
#include "physics/time_step_estimate.hpp"

namespace mpdem {

struct LinearLaw {
  static constexpr std::string_view kLaw = "linear", kCohesion = "none";
  static constexpr std::array<LawKey, 2> kKeys{{
      {"stiffness_normal", "N/m", kPositive, std::nullopt, true, "required", "normal stiffness k_n"},
      {"stiffness_tangential", "N/m", kNonNegative, std::nullopt, false, "2/7 stiffness_normal",
       "tangential stiffness k_t"},
  }};
  static constexpr std::size_t kNormalStiffness = kLawSlots;          // N/m, k_n
  static constexpr std::size_t kTangentialStiffness = kLawSlots + 1;  // N/m, k_t
  static constexpr std::size_t kEnd = kLawSlots + 2;
  static constexpr bool kElastic = false, kAdhesion = false;
  static constexpr bool kHysteresis = false;
  static constexpr bool kExactGeometry = false;

  static auto coefficients(const LawInputs& in) {
    const double k_n = in.key(kKeys[0]).value_or(0.0);  // the reader requires it
    return law_slots<LinearLaw>(k_n, in.key(kKeys[1]).value_or(2.0 / 7.0 * k_n));
  }
  // The exact (55) of the damped linear oscillator it was derived for.
  static double damping_ratio(double e) { return thesis_damping_ratio(e); }

  // k_n, k_t constant, f_el = k_n delta, energy 1/2 k_n delta^2. Not clamped: the restitution and
  // contact time of the damped linear oscillator then hold exactly.
  template <class Pair>
  static Stiffness stiffness(const Pair& law, double /*r_star*/, double overlap, double /*inv_reach*/ = 0.0) {
    Stiffness s;
    s.k_n = law.c[kNormalStiffness];
    s.f_el = s.k_n * overlap;
    s.k_t = law.c[kTangentialStiffness];
    s.energy = 0.5 * s.f_el * overlap;
    s.clamp = false;
    return s;
  }

  template <class Pair>
  static double contact_time(const Pair& c, double, double m, double, double) {
    return linear_contact_time(m, c.c[kNormalStiffness]);
  }
  template <class Pair>
  static double peak_overlap(const Pair& c, double, double m, double, double v) {
    return linear_peak_overlap(m, c.c[kNormalStiffness], v);
  }
  // delta ~ k^(-1/2).
  static constexpr std::string_view kStiffnessKey = "stiffness_normal", kSpringName = "linear spring";
  static constexpr double kOverlapExponent = 2.0;
};

}  // namespace mpdem
