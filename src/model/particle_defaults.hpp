#pragma once
// The properties a particle takes from its material when its input does not give them.
#include <cstddef>

#include "model/material.hpp"
#include "state/particles.hpp"

namespace mpdem {

// Sets particle i's density-independent material properties and initial temperature from m.
inline void take_material_properties(Particles& p, std::size_t i, const Material& m) {
  p.young[i] = m.young;
  p.poisson[i] = m.poisson;
  p.charge[i] = m.charge;
  p.heat_capacity[i] = m.heat_capacity;
  p.conductivity[i] = m.conductivity;
  p.emissivity[i] = m.emissivity;
  p.T[i] = m.temperature;
}

}  // namespace mpdem
