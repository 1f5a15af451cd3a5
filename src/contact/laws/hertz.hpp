#pragma once
// Hertz-Mindlin (physics.md sections 5-6): law = "hertz" (the default), no cohesion.
#include <cmath>

#include "contact/laws/law_interface.hpp"
#include "physics/restitution.hpp"
#include "physics/time_step_estimate.hpp"

namespace mpdem {

// The Hertz impact estimates, for the time-step advice and checks.max_overlap: undamped impacts at
// speed v (m/s) with effective mass m (kg), radius r (m) and modulus E* (Pa). Hertz's, and the
// adhesive laws' built on its spring: the adhesion is small against the kinetic energy of impacts
// fast enough to matter for either.
struct HertzEstimates {
  template <class Pair>
  static double contact_time(const Pair&, double E_star, double m, double r, double v) {
    return hertz_contact_time(m, E_star, r, v);
  }
  template <class Pair>
  static double peak_overlap(const Pair&, double E_star, double m, double r, double v) {
    return hertz_peak_overlap(m, E_star, r, v);
  }
  // For checks.max_overlap's advice: delta ~ E*^(-2/5).
  static constexpr std::string_view kStiffnessKey = "young", kSpringName = "Hertz";
  static constexpr double kOverlapExponent = 2.5;
};

struct HertzLaw : HertzEstimates {
  static constexpr std::string_view kLaw = "hertz", kCohesion = "none";
  static constexpr std::array<LawKey, 0> kKeys{};        // E and nu come from the materials
  static constexpr std::size_t kTwiceE = kLawSlots;      // Pa, 2 E*: k_n = 2 E* sqrt(r* delta)
  static constexpr std::size_t kEightG = kLawSlots + 1;  // Pa, 8 G*: k_t = 8 G* sqrt(r* delta) (65)
  static constexpr std::size_t kEnd = kLawSlots + 2;
  static constexpr bool kElastic = true, kAdhesion = false;
  static constexpr bool kHysteresis = false;
  static constexpr bool kExactGeometry = false;

  static auto coefficients(const LawInputs& in) { return law_slots<HertzLaw>(2.0 * in.E_star, 8.0 * in.G_star); }
  // The Hertz calibration of the damping ratio (section 5 Departure).
  static double damping_ratio(double e) { return damping_ratio_for_restitution(e); }

  // With root = sqrt(r* delta): k_n = 2 E* root, f_el = 4/3 E* sqrt(r*) delta^(3/2) = 2/3 k_n delta
  // (49), k_t = 8 G* root (65), energy 8/15 E* sqrt(r*) delta^(5/2) = 2/5 f_el delta (section 12).
  template <class Pair>
  static Stiffness stiffness(const Pair& law, double r_star, double overlap, double /*inv_reach*/ = 0.0) {
    Stiffness s;
    const double root = std::sqrt(r_star * overlap);  // m
    s.k_n = law.c[kTwiceE] * root;
    s.f_el = (2.0 / 3.0) * s.k_n * overlap;
    s.k_t = law.c[kEightG] * root;
    s.energy = 0.4 * s.f_el * overlap;
    return s;
  }
};

}  // namespace mpdem
