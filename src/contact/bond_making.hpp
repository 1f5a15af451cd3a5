#pragma once
// The parallel bonds a scene makes at t = 0 (docs/scene.md "[bonds]"): by the gap rule, between
// particles whose surface gap |x_j - x_i| - R_i - R_j is below the `gap` of their materials'
// BondLaw (the minimum image across periodic faces), found with a cell grid in O(N); and the bond
// CSV's rows, their ids resolved to indices. Members of one clump body are never bonded to each
// other (they move rigidly), nor are two fixed particles (a fixed body's members count as fixed).
#include <cstdint>
#include <vector>

#include "model/bond_rules.hpp"
#include "model/scene.hpp"
#include "state/particles.hpp"

namespace mpdem {

struct MadeBond {
  std::uint32_t i, j;  // particle indices into p, with p.id[i] < p.id[j]
  friend bool operator==(const MadeBond&, const MadeBond&) = default;
};

// m, the centre distance of i and j (the minimum image along the domain's periodic axes).
double bond_length(const Model& model, const Particles& p, std::uint32_t i, std::uint32_t j);

// The gap rule's bonds among the owned particles, sorted by (id_i, id_j).
std::vector<MadeBond> gap_bonds(const Model& model, const Particles& p);
// The listed bonds (Params::bonds.listed) as indices, sorted by (id_i, id_j), leaving out what
// make_bonds leaves out. Throws InputError at the CSV line for an id no particle has (the scene
// reader refuses those at load: a scene built in code may not have been checked).
std::vector<MadeBond> listed_bonds(const Model& model, const Particles& p);

// The bonds made at t = 0: the gap rule's and the listed ones (ids resolved to indices), without
// duplicates, sorted by (id_i, id_j); bonds between two fixed particles and clump members of the
// same body are left out, as are listed bonds between materials that [[bonds.pair]] keeps apart.
std::vector<MadeBond> make_bonds(const Model& model, const Particles& p);
// The union of two lists of bonds of p, sorted by (id_i, id_j), each bond once.
std::vector<MadeBond> bond_union(const Particles& p, std::vector<MadeBond> a, const std::vector<MadeBond>& b);

}  // namespace mpdem
