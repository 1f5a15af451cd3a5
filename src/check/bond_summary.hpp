#pragma once
// What `mpdem check` prints about parallel bonds (docs/scene.md "[bonds]"): the bonds the scene
// makes at t = 0 (by the gap rule, from the bond CSV, their union), the particles left without a
// bond, those whose material is bonded to no material, the bonds' lengths, and the bonds' time
// step 2 sqrt(m* / (k_n A)) (k_n = E_b / L, A = pi R_b^2), which the time-step advice includes.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "model/scene.hpp"

namespace mpdem {

struct BondSummary {
  std::size_t by_gap = 0;                         // bonds the gap rule makes
  std::size_t listed = 0;                         // bonds of the bond CSV that are made
  std::size_t made = 0;                           // their union (each bond once)
  std::size_t isolated = 0;                       // particles without a bond
  std::vector<std::int64_t> isolated_ids;         // the kListedIds smallest of their ids, ascending
  std::size_t unbondable = 0;                     // particles whose material is bonded to none
  std::vector<std::string> unbondable_materials;  // those materials' names
  double length_min = 0.0, length_max = 0.0;      // m, centre distances of the bonds at t = 0
  double time_step = 0.0;                         // s, smallest 2 sqrt(m* / (k_n A)) over the bonds (0: no bond)
};

// The summary of a scene with [bonds]; all zero without.
BondSummary bond_summary(const Scene& scene);

// The lines `mpdem check` prints; empty when the scene has no [bonds].
std::vector<std::string> bond_summary_lines(const Scene& scene);

}  // namespace mpdem
