#pragma once
// Capillary liquid bridges in the scene file (docs/scene.md "[liquid_bridge]"): the
// [liquid_bridge] defaults and the liquid_bridge table of a [[contact.pair]] entry.
#include <span>
#include <string_view>

#include "io/toml_section.hpp"
#include "model/params.hpp"

namespace mpdem {

// The keys of a liquid_bridge table of a [[contact.pair]] entry.
std::span<const std::string_view> liquid_bridge_keys();

// Reads [liquid_bridge] of the scene's root table into c.liquid_bridge.
void read_liquid_bridge(const TomlSection& root, ContactParams& c);

// Reads an entry's liquid_bridge table (s) and checks the bridge it makes with the defaults d:
// a known model, and with bridges on a surface tension and one liquid amount.
LiquidBridgeKeys read_pair_liquid_bridge(const TomlSection& s, const LiquidBridgeParams& d);

}  // namespace mpdem
