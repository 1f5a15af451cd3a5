#pragma once
// Materials by index: every particle and barrier element takes its constants (density, E, nu,
// heat capacity, conductivity, emissivity) from its material. A particle or barrier CSV may give
// such a value per row; such a row gets a variant of its material (a copy with the row's values,
// named "<material>#<k>", Material::variant_of set), so that the contact tables, indexed by
// material, see the row's own values. [[contact.pair]] entries naming a material apply to its
// variants too.
#include "model/scene.hpp"

namespace mpdem {

// At most this many materials after variants are made: the contact tables grow with its square.
inline constexpr std::size_t kMaxMaterials = 256;

// Points every particle and element at a material whose constants are its own, adding variants
// (and, for particles or elements without any material, a material made from their values).
// Throws InputError (naming `source`) when more than kMaxMaterials would be needed.
void resolve_material_variants(Model& model, Particles& particles, Barriers& barriers, const std::string& source);

}  // namespace mpdem
