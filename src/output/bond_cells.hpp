#pragma once
// The bonds as output rows (io/bond_vtu_writer.hpp BondCells): the bond VTU snapshots and the
// Python module's sim.bonds read the same values, the stresses included.
#include <span>

#include "contact/bonds.hpp"
#include "io/bond_vtu_writer.hpp"
#include "state/particles.hpp"

namespace mpdem {

// One row per bond of `bonds`, in their order; `p`'s owned particles hold every bond's two (on
// several ranks: the gathered particles). The line runs from particle i's centre to the image of
// particle j nearest to it (`period`: the domain's period per axis, 0 where not periodic), so no
// line spans a periodic box. A broken bond keeps the forces of its last commit before the break.
// Throws std::runtime_error when a bond's particle is not in p.
BondCells bond_cells(std::span<const BondRecord> bonds, const Particles& p, const Vec3& period);

}  // namespace mpdem
