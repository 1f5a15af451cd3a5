#include "model/scene.hpp"

namespace mpdem {

int Model::material_index(const std::string& name) const {
  for (std::size_t m = 0; m < materials.size(); ++m)
    if (materials[m].name == name) return static_cast<int>(m);
  return -1;
}

int Model::clump_index(const std::string& name) const {
  for (std::size_t c = 0; c < clumps.size(); ++c)
    if (clumps[c].name == name) return static_cast<int>(c);
  return -1;
}

}  // namespace mpdem
