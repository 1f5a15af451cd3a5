#pragma once
// Derjaguin-Muller-Toporov adhesion (Derjaguin, Muller & Toporov 1975, J. Colloid Interface Sci.
// 53, 314): law = "hertz", cohesion = "dmt". The Hertz force less a constant pull,
//   F = 4/3 E* sqrt(r*) delta^(3/2) - 2 pi w r*,
// w the surface energy (J/m^2), acting while the spheres overlap (delta > 0). Quasi-statically the
// contact holds while the net force would: two spheres pulled apart part at the pull-off
// 2 pi w r* (a sphere on a barrier: r* = R), where delta reaches 0.
// - Clamp: the net force, dashpot included, is never more attractive than the pull-off
//   (f_n >= -2 pi w r*); the dashpot opposes the motion but cannot hold the surfaces beyond it.
// - Coulomb's limit and rolling resistance scale with the load pressing the surfaces together,
//   f_n + 2 pi w r* >= 0 (the Hertz part: the adhesion acts as an extra normal load).
// - Energy: the potential 8/15 E* sqrt(r*) delta^(5/2) - 2 pi w r* delta, zero at touching, so
//   the force's jump to zero at separation does no work and the energy balance stays closed.
// - Near delta = 0: sqrt(r* delta) with delta >= 0 and no division, so nothing is NaN; k_n and
//   the dashpot vanish there (the Hertz stiffness), the pull stays.
// - Damping: the Hertz calibration of the restitution (the adhesion is not in it: with w > 0
//   a slow impact sticks, as it does in nature).
#include <cmath>
#include <numbers>

#include "contact/laws/hertz.hpp"
#include "contact/laws/law_interface.hpp"
#include "physics/restitution.hpp"

namespace mpdem {

struct DmtLaw : HertzEstimates {  // the Hertz impact estimates
  static constexpr std::string_view kLaw = "hertz", kCohesion = "dmt";
  static constexpr std::array<LawKey, 1> kKeys{{
      {"surface_energy", "J/m^2", kNonNegative, 0.0, false, "0", "surface energy w: pull-off 2 pi w r*"},
  }};
  static constexpr std::size_t kTwiceE = HertzLaw::kTwiceE;  // Pa, 2 E*, as Hertz
  static constexpr std::size_t kEightG = HertzLaw::kEightG;  // Pa, 8 G*, as Hertz
  static constexpr std::size_t kTwoPiW = kLawSlots + 2;      // N/m, 2 pi w: the pull-off is kTwoPiW r*
  static constexpr std::size_t kEnd = kLawSlots + 3;
  static constexpr bool kElastic = true, kAdhesion = true;
  static constexpr bool kHysteresis = false;
  static constexpr bool kExactGeometry = false;

  static auto coefficients(const LawInputs& in) {
    return law_slots<DmtLaw>(2.0 * in.E_star, 8.0 * in.G_star, 2.0 * std::numbers::pi * in.key(kKeys[0]).value_or(0.0));
  }
  static double damping_ratio(double e) { return damping_ratio_for_restitution(e); }

  // The Hertz spring (same slots) less the pull.
  template <class Pair>
  static Stiffness stiffness(const Pair& law, double r_star, double overlap, double /*inv_reach*/ = 0.0) {
    Stiffness s = HertzLaw::stiffness(law, r_star, overlap);
    s.adhesion = law.c[kTwoPiW] * r_star;
    s.load_offset = s.adhesion;
    s.f_el -= s.adhesion;
    s.energy -= s.adhesion * overlap;
    return s;
  }
};

}  // namespace mpdem
