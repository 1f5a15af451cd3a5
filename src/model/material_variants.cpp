#include "model/material_variants.hpp"

#include <stdexcept>
#include <utility>

#include "core/input_error.hpp"

namespace mpdem {

MaterialVariants::Key MaterialVariants::key_of(int base, const Material& m) {
  return {base, m.density, m.young, m.poisson, m.heat_capacity, m.conductivity, m.emissivity};
}

MaterialVariants::MaterialVariants(Model& model, std::string source) : model_(model), source_(std::move(source)) {
  for (std::size_t m = 0; m < model.materials.size(); ++m) {
    const Material& mat = model.materials[m];
    known_.emplace(key_of(mat.variant_of >= 0 ? mat.variant_of : static_cast<int>(m), mat), static_cast<int>(m));
  }
}

int MaterialVariants::find(int current, const Material& wanted) {
  const bool valid = current >= 0 && current < static_cast<int>(model_.materials.size());
  const int base = valid ? (model_.materials[current].variant_of >= 0 ? model_.materials[current].variant_of : current)
                         : -1;
  if (valid && key_of(base, model_.materials[current]) == key_of(base, wanted)) return current;
  if (const auto it = known_.find(key_of(base, wanted)); it != known_.end()) return it->second;
  if (model_.materials.size() >= kMaxMaterials)
    throw InputError(source_, 0, "",
                     "more than " + std::to_string(kMaxMaterials) +
                         " materials would be needed: per-particle or per-triangle density, young, poisson, "
                         "heat_capacity, conductivity or emissivity columns make a material variant for every "
                         "distinct set of values; define [[material]] entries instead");
  Material m = wanted;
  m.variant_of = base;
  m.name = (base >= 0 ? model_.materials[base].name : std::string("unnamed")) + "#" +
           std::to_string(model_.materials.size());
  model_.materials.push_back(m);
  const int index = static_cast<int>(model_.materials.size()) - 1;
  known_.emplace(key_of(base, m), index);
  return index;
}

void resolve_material_variants(Model& model, Particles& p, Barriers& b, const std::string& source) {
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.material[i] < 0 || p.material[i] >= static_cast<int>(model.materials.size()))
      throw std::logic_error("particle id " + std::to_string(p.id[i]) + " has no material of the model");
  MaterialVariants variants(model, source);
  b.material.resize(b.size(), -1);
  for (std::size_t e = 0; e < b.size(); ++e) {
    const int m = b.material[e];
    Material wanted = m >= 0 && m < static_cast<int>(model.materials.size()) ? model.materials[m] : Material{};
    wanted.young = b.young[e];
    wanted.poisson = b.poisson[e];
    b.material[e] = variants.find(m, wanted);
  }
}

}  // namespace mpdem
