#pragma once
// What may be bonded (docs/scene.md "[bonds]"): the bond law of every pair of materials by index,
// and the particles that cannot move (two of them are never bonded: such a bond could never act).
// Shared by the scene reader's checks of the bond CSV and the making of the bonds at t = 0.
#include <cstdint>
#include <vector>

#include "model/bond_params.hpp"
#include "model/scene.hpp"
#include "state/particles.hpp"

namespace mpdem {

// The law of each pair of materials by index [materials x materials], row-major; a variant
// material (per-row CSV values) takes its base material's name.
std::vector<BondLaw> bond_laws(const Model& model);

// [owned particles] 1 when the particle cannot move under forces: fixed, or a member of a fixed body.
std::vector<std::uint8_t> held_fixed(const Particles& p);

}  // namespace mpdem
