#pragma once
// Simplified JKR (LIGGGHTS' cohesion model sjkr): law = "hertz", cohesion = "sjkr" (docs/physics.md
// section 16). The Hertz force less an attraction k A while the spheres overlap (delta > 0), k the
// cohesion energy density (J/m^3) and A = pi a^2 the cross-section of the two spheres' overlap
// lens. With kappa = 1 / (R_i + R_j) (inv_reach) and r* = R_i R_j kappa, the exact lens radius is
//   a^2 = delta (2 - delta kappa) (4 r* - 2 delta + delta^2 kappa) / (4 (1 - delta kappa)^2)
// (= R_i^2 - ((d^2 + R_i^2 - R_j^2) / (2 d))^2 at the centre distance d = R_i + R_j - delta; a
// barrier, kappa = 0, r* = R: delta (2 R - delta)). Since the lens volume V(delta) has dV/d(delta)
// = A, the attraction's potential is -k V with
//   V = pi delta^2 (12 r* - 4 delta + delta^2 kappa) / (12 (1 - delta kappa))
// (a barrier: the spherical cap pi delta^2 (R - delta / 3)).
// - k_n and k_t: the Hertz ones (the dashpot and the time step as Hertz, as LIGGGHTS).
// - Clamp: the net force is never more attractive than -k A; Coulomb's limit and rolling
//   resistance scale with f_n + k A (the attraction acts as an extra load, as DMT's).
// - At delta = 0: a = 0, V = 0, the force is the Hertz one, 0: nothing divides by the overlap.
#include <cmath>
#include <numbers>

#include "contact/laws/hertz.hpp"
#include "contact/laws/law_interface.hpp"
#include "physics/restitution.hpp"

namespace mpdem {

struct SjkrLaw : HertzEstimates {  // the Hertz impact estimates
  static constexpr std::string_view kLaw = "hertz", kCohesion = "sjkr";
  static constexpr std::array<LawKey, 1> kKeys{{
      {"cohesion_energy_density", "J/m^3", kNonNegative, 0.0, false, "0",
       "cohesion energy density k: attraction k times the overlap's cross-section"},
  }};
  static constexpr std::size_t kTwiceE = HertzLaw::kTwiceE;  // Pa, 2 E*, as Hertz
  static constexpr std::size_t kEightG = HertzLaw::kEightG;  // Pa, 8 G*, as Hertz
  static constexpr std::size_t kPiK = kLawSlots + 2;         // J/m^3, pi k: the attraction is kPiK a^2
  static constexpr std::size_t kEnd = kLawSlots + 3;
  static constexpr bool kElastic = true, kAdhesion = true;
  static constexpr bool kHysteresis = false;
  static constexpr bool kExactGeometry = true;

  static auto coefficients(const LawInputs& in) {
    return law_slots<SjkrLaw>(2.0 * in.E_star, 8.0 * in.G_star, std::numbers::pi * in.key(kKeys[0]).value_or(0.0));
  }
  static double damping_ratio(double e) { return damping_ratio_for_restitution(e); }

  // The overlap lens at overlap delta >= 0 (kappa = inv_reach): a^2 (m^2) and V / pi (m^3).
  struct Lens {
    double radius_squared = 0.0;
    double volume_per_pi = 0.0;
  };
  static Lens lens(double r_star, double delta, double kappa) {
    const double u = 1.0 - delta * kappa;  // d / (R_i + R_j), > 0 unless the centres coincide
    const double v = u > 1e-12 ? u : 1e-12;
    const double dk = delta * kappa;
    return {delta * (2.0 - dk) * (4.0 * r_star - 2.0 * delta + delta * dk) / (4.0 * v * v),
            delta * delta * (12.0 * r_star - 4.0 * delta + delta * dk) / (12.0 * v)};
  }

  // The Hertz spring (same slots) less the attraction.
  template <class Pair>
  static Stiffness stiffness(const Pair& law, double r_star, double overlap, double inv_reach = 0.0) {
    const double delta = overlap > 0.0 ? overlap : 0.0;
    Stiffness s = HertzLaw::stiffness(law, r_star, delta);
    const Lens l = lens(r_star, delta, inv_reach);
    s.adhesion = law.c[kPiK] * l.radius_squared;
    s.load_offset = s.adhesion;
    s.f_el -= s.adhesion;
    s.energy -= law.c[kPiK] * l.volume_per_pi;
    return s;
  }
};

}  // namespace mpdem
