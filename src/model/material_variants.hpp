#pragma once
// Materials by index: every particle and barrier element takes its constants (density, E, nu,
// heat capacity, conductivity, emissivity) from its material. A particle or barrier CSV may give
// such a value per row; such a row gets a variant of its material (a copy with the row's values,
// named "<material>#<k>", Material::variant_of set), so that the contact tables, indexed by
// material, see the row's own values. [[contact.pair]] entries naming a material apply to its
// variants too.
#include <map>
#include <string>
#include <tuple>

#include "model/scene.hpp"

namespace mpdem {

// At most this many materials after variants are made: the contact tables grow with its square.
inline constexpr std::size_t kMaxMaterials = 256;

// Finds or makes the materials with given constants among a material and its variants.
class MaterialVariants {
 public:
  // `source` names the input in the message when more than kMaxMaterials would be needed.
  MaterialVariants(Model& model, std::string source);
  // The index of the material with `wanted`'s constants among `current` (an index of the model,
  // or -1: none) and its variants; a new variant (or, for -1, a new material) when none has them.
  // Throws InputError when the model would exceed kMaxMaterials.
  int find(int current, const Material& wanted);

 private:
  using Key = std::tuple<int, double, double, double, double, double, double>;  // base, constants
  static Key key_of(int base, const Material& m);
  Model& model_;
  std::string source_;
  std::map<Key, int> known_;
};

// Points every barrier element at a material whose E and nu are its own (Barriers::young,
// poisson: the barrier CSV's per-row values or the source's material; a rigid source's E is
// kRigidYoung, so its elements share a rigid variant with the material's other constants),
// adding variants, and checks that every particle has a material of the model (particles get
// theirs when read).
void resolve_material_variants(Model& model, Particles& particles, Barriers& barriers, const std::string& source);

}  // namespace mpdem
