#pragma once
// Capillary liquid bridges (physics.md "Capillary liquid bridges"): the resolved constants of one
// pair of materials (BridgeLaw, from [liquid_bridge] and [[contact.pair]] liquid_bridge tables,
// contact/contact_table.hpp) and the force of one bridge. A bridge forms when the surfaces
// first touch and holds until the gap exceeds the rupture distance (the kernels keep that
// state); while it holds it pulls the surfaces together with the capillary force of its model
// (Willett: willett.hpp, Rabinovich: rabinovich.hpp) and, with a viscosity, resists the normal
// motion with the lubrication force of two spheres.
// Geometry as the contact laws take it: r* = R_i R_j / (R_i + R_j) and kappa = 1 / (R_i + R_j)
// for two particles; r* = R and kappa = 0 for a particle on a barrier element (a plane).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "contact/bridges/rabinovich.hpp"
#include "contact/bridges/willett.hpp"

namespace mpdem {

enum class BridgeModel : std::int32_t { none = 0, willett = 1, rabinovich = 2 };

// One material pair's resolved bridge constants (ContactTable).
struct BridgeLaw {
  BridgeModel model = BridgeModel::none;
  double surface_tension = 0.0;  // N/m, gamma
  double contact_angle = 0.0;    // rad, theta in [0, pi/2]
  double volume = 0.0;           // m^3 per bridge, > 0; 0: from liquid_fraction
  double liquid_fraction = 0.0;  // -, used when volume == 0 (bridge_volume)
  double viscosity = 0.0;        // Pa s, mu (0: no viscous force)
  double min_gap = 0.0;          // -, relative: the lubrication term's smallest gap is min_gap r*
};

// What one bridge does at one evaluation.
struct BridgeForce {
  double fn = 0.0;  // N, along the contact normal on the first member: capillary attraction (<= 0) plus viscous
  double energy =
      0.0;  // J, the capillary force's potential: 0 at touching, rising with the gap (the work to open it to S)
  double damping = 0.0;  // W, >= 0, the viscous term's dissipated power
};

// m^3, the bridge's liquid: `volume`, or from liquid_fraction phi a share of the members' volumes,
//   V = phi (V_i + V_j) / 2 (two particles),   V = phi V_i / 2 (a particle on a barrier),
// with R_i^3 + R_j^3 = s^3 - 3 p s from s = R_i + R_j = 1/kappa and p = R_i R_j = r*/kappa.
inline double bridge_volume(const BridgeLaw& b, double r_star, double inv_reach) {
  const double s = inv_reach > 0.0 ? 1.0 / inv_reach : 0.0;
  const double cubes = inv_reach > 0.0 ? s * s * s - 3.0 * r_star * s * s : r_star * r_star * r_star;
  return b.volume > 0.0 ? b.volume : b.liquid_fraction * (2.0 / 3.0) * std::numbers::pi * cubes;
}

// m, the rupture distance S_c = (1 + theta/2) V^(1/3) (Lian, Thornton & Adams 1993, J. Colloid
// Interface Sci. 161, 138; theta in rad).
inline double bridge_rupture_distance(const BridgeLaw& b, double r_star, double inv_reach) {
  return (1.0 + 0.5 * b.contact_angle) * std::cbrt(bridge_volume(b, r_star, inv_reach));
}

// m, the largest rupture distance of the law between particles of radius <= r_max (barrier: a
// particle on a barrier element), for the neighbour range; 0 without a bridge. The volume from a
// liquid fraction is largest for the largest particles: 2 r_max^3 (pair) or r_max^3 (barrier)
// for R_i^3 + R_j^3.
inline double bridge_reach(const BridgeLaw& b, double r_max, bool barrier) {
  if (b.model == BridgeModel::none) return 0.0;
  const double cubes = (barrier ? 1.0 : 2.0) * r_max * r_max * r_max;
  const double v = b.volume > 0.0 ? b.volume : b.liquid_fraction * (2.0 / 3.0) * std::numbers::pi * cubes;
  return (1.0 + 0.5 * b.contact_angle) * std::cbrt(v);
}

// The bridge at overlap (m; > 0 in contact, the gap S = max(-overlap, 0)) and normal rate
// v_n = (v_i - v_j).n (m/s, < 0 approaching); called only while the bridge holds.
// - Capillary: the model's force at S (in contact: its value at S = 0), attractive. Its
//   potential is the work to open the gap to S, and -F(0) overlap in contact (a constant pull
//   there), so that d(energy)/d(overlap) = fn everywhere (as the laws' f_el = dU/d(delta)).
// - Viscous: the lubrication force of two spheres (Adams & Perchard 1985),
//   F_v = -6 pi mu r*^2 v_n / max(S, min_gap r*), in contact too (S = 0 -> min_gap r*); r* is the
//   reduced radius (a sphere on a plane: R). Its power -F_v v_n >= 0 is dissipated.
inline BridgeForce bridge_force(const BridgeLaw& b, double r_star, double inv_reach, double overlap,
                                double normal_rate) {
  if (b.model == BridgeModel::none) return {};
  const double gap = std::max(-overlap, 0.0), pressed = std::max(overlap, 0.0);
  const double R = 2.0 * r_star, V = bridge_volume(b, r_star, inv_reach);
  double f = 0.0, work = 0.0;
  if (b.model == BridgeModel::willett) {
    const double f0 = 2.0 * std::numbers::pi * R * b.surface_tension * std::cos(b.contact_angle);
    const double k = std::sqrt(R / V);
    f = willett_force(f0, k, gap);
    work = willett_energy(f0, k, gap);
  } else {
    const RabinovichBridge rb{R, b.surface_tension, b.contact_angle, V};
    f = rabinovich_force(rb, gap);
    work = rabinovich_energy(rb, gap);
  }
  const double fv = -6.0 * std::numbers::pi * b.viscosity * r_star * r_star * normal_rate /
                    std::max(gap, b.min_gap * r_star);
  return {-f + fv, work - f * pressed, -fv * normal_rate};
}

}  // namespace mpdem
