#pragma once
// TEMPORARY stand-in (replaced by the bridge helper's branch at merge): the interface only.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace mpdem {

enum class BridgeModel : std::int32_t { none = 0, willett = 1, rabinovich = 2 };
struct BridgeLaw {
  BridgeModel model = BridgeModel::none;
  double surface_tension = 0.0;
  double contact_angle = 0.0;
  double volume = 0.0;
  double liquid_fraction = 0.0;
  double viscosity = 0.0;
  double min_gap = 0.0;
};
struct BridgeForce {
  double fn = 0.0;
  double energy = 0.0;
  double damping = 0.0;
};
inline double bridge_volume(const BridgeLaw& b, double, double) { return b.volume; }
inline double bridge_rupture_distance(const BridgeLaw& b, double r, double k) {
  return (1.0 + 0.5 * b.contact_angle) * std::cbrt(bridge_volume(b, r, k));
}
inline BridgeForce bridge_force(const BridgeLaw& b, double r_star, double k, double overlap, double) {
  const double R = 2.0 * r_star, V = bridge_volume(b, r_star, k), S = std::max(-overlap, 0.0);
  const double sh = S * std::sqrt(R / V);
  return {-2.0 * std::numbers::pi * R * b.surface_tension * std::cos(b.contact_angle) / (1.0 + 1.05 * sh + 2.5 * sh * sh),
          0.0, 0.0};
}

}  // namespace mpdem
