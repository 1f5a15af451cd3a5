#pragma once
// The bond VTU snapshots (docs/output.md "Bond VTU"): one VTK_LINE cell per parallel bond between
// its two particles' centres, in the [output] format (io/vtk_xml.hpp), written atomically. The
// file format only: output/bond_cells.hpp fills the cells from the bonds and the particles.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/vec3.hpp"
#include "model/params.hpp"

namespace mpdem {

// The cells of a bond snapshot, one row per bond (arrays [bonds]); forces and moments are those on
// particle j (id_i < id_j), as contact/bonds.hpp keeps them.
struct BondCells {
  std::vector<Vec3> from, to;            // m, the centres of particle i and of particle j's image nearest to it
  std::vector<std::int64_t> id_i, id_j;  // -, the particles' ids
  std::vector<std::uint8_t> intact;      // 1: acts, 0: broken
  std::vector<double> normal_force;      // N, F_n (> 0 compression)
  std::vector<Vec3> shear_force;         // N, F_s
  std::vector<double> twisting_moment;   // N m, M_n about the bond's axis
  std::vector<Vec3> bending_moment;      // N m, M_s
  std::vector<double> sigma_max;         // Pa, the largest tensile stress on the rim
  std::vector<double> tau_max;           // Pa, the largest shear stress on the rim
  std::vector<double> length;            // m, L: the centre distance when the bond was made
  std::size_t size() const { return id_i.size(); }
};

// Points: two per cell (the line's own ends, `from` then `to`); CellData: the arrays above but
// `from` and `to` in that order; FieldData "TimeValue" = time (s).
void write_bonds_vtu(const std::filesystem::path& file, const BondCells& cells, double time,
                     VtkFormat format = VtkFormat::Binary);

}  // namespace mpdem
