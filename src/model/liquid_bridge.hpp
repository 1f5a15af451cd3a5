#pragma once
// The keys of capillary liquid bridges as given: [liquid_bridge] (the defaults) and the
// liquid_bridge table of a [[contact.pair]] entry (docs/scene.md "[liquid_bridge]"), and how an
// entry's keys override the defaults. The contact table resolves them per pair of materials
// (contact/contact_table.cpp) into the bridge law (contact/bridges/bridge_law.hpp).
#include <cstddef>
#include <optional>
#include <string>

namespace mpdem {

// Unset: not given (the documented default, or the defaults' value for an entry).
struct LiquidBridgeKeys {
  std::optional<std::string> model;        // "willett" (default), "rabinovich" or "none"
  std::optional<double> surface_tension;   // N/m, gamma > 0 (required when bridges are on)
  std::optional<double> contact_angle;     // rad, theta in [0, pi/2] (the key is in degrees; default 0)
  std::optional<double> volume;            // m^3 per bridge, > 0; exclusive with liquid_fraction
  std::optional<double> liquid_fraction;   // -, phi in (0, 1): V = phi (V_i + V_j) / 2, at a barrier phi V_i / 2
  std::optional<double> viscosity;         // Pa s, mu >= 0 (default 0: no viscous force)
  std::optional<double> min_gap;           // -, > 0, the lubrication term's smallest gap / r* (default kMinGap)
  static constexpr double kMinGap = 1e-3;  // -, min_gap's default
  static constexpr const char* kModel = "willett";  // model's default
};

// The defaults with an entry's keys over them, key by key; a volume given replaces a liquid
// fraction and the other way round (the two are one choice).
inline LiquidBridgeKeys overridden(LiquidBridgeKeys base, const LiquidBridgeKeys& over) {
  if (over.model) base.model = over.model;
  if (over.surface_tension) base.surface_tension = over.surface_tension;
  if (over.contact_angle) base.contact_angle = over.contact_angle;
  if (over.volume || over.liquid_fraction) {
    base.volume = over.volume;
    base.liquid_fraction = over.liquid_fraction;
  }
  if (over.viscosity) base.viscosity = over.viscosity;
  if (over.min_gap) base.min_gap = over.min_gap;
  return base;
}

// [liquid_bridge] and its barrier switch.
struct LiquidBridgeParams {
  std::optional<LiquidBridgeKeys> defaults;  // [liquid_bridge] given: its keys
  bool barriers = true;                      // the defaults also apply between particles and barrier elements
};

}  // namespace mpdem
