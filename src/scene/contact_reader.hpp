#pragma once
// The [contact] table of a scene (docs/scene.md "Contact"): the default laws of particle-particle
// and particle-barrier contacts and the [[contact.pair]] overrides per pair of materials.
#include <string>
#include <string_view>

#include "io/toml_section.hpp"
#include "model/scene.hpp"

namespace mpdem {

// Reads [contact] of the scene's root table into c; the materials must be read already.
void read_contact(const TomlSection& root, const Model& model, ContactParams& c);

// "unknown material 'x' (known: a, b)" at key k unless `name` is one of the model's materials.
void check_material(const TomlSection& s, std::string_view k, const std::string& name, const Model& model);

}  // namespace mpdem
