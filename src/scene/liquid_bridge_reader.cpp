#include "scene/liquid_bridge_reader.hpp"

#include <array>
#include <numbers>
#include <string>

#include "core/value_range.hpp"

namespace mpdem {

namespace {

constexpr std::array<std::string_view, 7> kKeys{"model",           "surface_tension", "contact_angle", "volume",
                                                "liquid_fraction", "viscosity",       "min_gap"};
constexpr std::array<std::string_view, 8> kSectionKeys{
    "model", "surface_tension", "contact_angle", "volume", "liquid_fraction", "viscosity", "min_gap", "barriers"};

// The keys of one table, each range-checked; the contact angle from degrees to radians.
LiquidBridgeKeys read_keys(const TomlSection& s) {
  LiquidBridgeKeys k;
  if (s.has("model")) {
    const std::string m = *s.string("model");
    if (m != "willett" && m != "rabinovich" && m != "none")
      s.fail("model", "expected \"willett\", \"rabinovich\" or \"none\", got \"" + m + "\"");
    k.model = m;
  }
  k.surface_tension = s.number("surface_tension", kPositive);
  if (const auto deg = s.number("contact_angle", Range{0.0, 90.0, true, true}))
    k.contact_angle = *deg * std::numbers::pi / 180.0;
  k.volume = s.number("volume", kPositive);
  k.liquid_fraction = s.number("liquid_fraction", Range{0.0, 1.0, false, false});
  if (k.volume && k.liquid_fraction) s.fail("liquid_fraction", "give either volume or liquid_fraction, not both");
  k.viscosity = s.number("viscosity", kNonNegative);
  k.min_gap = s.number("min_gap", kPositive);
  return k;
}

// With bridges on (a model other than "none"), the resolved keys need a surface tension and one
// liquid amount: named at this table's key when it could have given them.
void check_complete(const TomlSection& s, const LiquidBridgeKeys& k) {
  if (k.model.value_or(LiquidBridgeKeys::kModel) == "none") return;
  if (!k.surface_tension) s.fail("surface_tension", "missing required key (N/m, > 0): liquid bridges need it");
  if (!k.volume && !k.liquid_fraction)
    s.fail("volume", "missing required key: give volume (m^3 per bridge, > 0) or liquid_fraction (-, in (0, 1))");
}

}  // namespace

std::span<const std::string_view> liquid_bridge_keys() { return kKeys; }

void read_liquid_bridge(const TomlSection& root, ContactParams& c) {
  const auto s = root.table("liquid_bridge", std::span<const std::string_view>(kSectionKeys));
  if (!s) return;
  c.liquid_bridge.defaults = read_keys(*s);
  s->get("barriers", c.liquid_bridge.barriers);
  check_complete(*s, *c.liquid_bridge.defaults);
}

LiquidBridgeKeys read_pair_liquid_bridge(const TomlSection& s, const LiquidBridgeParams& d) {
  LiquidBridgeKeys k = read_keys(s);
  check_complete(s, overridden(d.defaults.value_or(LiquidBridgeKeys{}), k));
  return k;
}

}  // namespace mpdem
