#include "model/bond_rules.hpp"

#include <string>
#include <unordered_map>

namespace mpdem {

std::vector<BondLaw> bond_laws(const Model& model) {
  const std::vector<Material>& m = model.materials;
  const std::size_t n = m.size();
  std::vector<std::string> names(n);
  for (std::size_t k = 0; k < n; ++k)
    names[k] = m[k].variant_of >= 0 ? m[static_cast<std::size_t>(m[k].variant_of)].name : m[k].name;
  std::vector<BondLaw> laws(n * n);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a; b < n; ++b)
      laws[a * n + b] = laws[b * n + a] = bond_law(model.params.bonds, names[a], names[b]);
  return laws;
}

std::vector<std::uint8_t> held_fixed(const Particles& p) {
  std::unordered_map<std::int64_t, std::uint8_t> body_fixed;  // body id -> fixed
  for (std::size_t b = 0; b < p.bodies.size(); ++b) body_fixed.emplace(p.bodies.id[b], p.bodies.fixed[b]);
  std::vector<std::uint8_t> held(p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    held[i] = p.fixed[i] != 0 || (p.body[i] != kNoBody && body_fixed.at(p.body[i]) != 0);
  return held;
}

}  // namespace mpdem
