#pragma once
// TEMPORARY (coordinator's stand-in until helper bond-a's search lands): the bonds made at t = 0.
#include <cstdint>
#include <vector>

#include "model/scene.hpp"

namespace mpdem {

struct MadeBond {
  std::uint32_t i, j;  // particle indices into p, with p.id[i] < p.id[j]
};
// The bonds made at t = 0: the gap rule's and the listed ones, without duplicates, sorted by ids.
std::vector<MadeBond> make_bonds(const Model& model, const Particles& p);

}  // namespace mpdem
