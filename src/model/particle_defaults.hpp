#pragma once
// The per-particle values a particle takes from its material when its input does not give them.
#include <cstddef>

#include "model/material.hpp"
#include "state/particles.hpp"

namespace mpdem {

// Sets particle i's default charge and initial temperature from its material m (the material's
// constants are looked up through the particle's material index, not copied).
inline void take_material_properties(Particles& p, std::size_t i, const Material& m) {
  p.charge[i] = m.charge;
  p.T[i] = m.temperature;
}

}  // namespace mpdem
