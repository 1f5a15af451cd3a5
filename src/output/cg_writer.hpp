#pragma once
// Coarse-grained fields on disk (docs/output.md "Coarse-grained fields"): a grid as VTK
// ImageData (.vti, point data at the grid points) and a profile as rows of a CSV log.
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/coarse_grain.hpp"
#include "model/params.hpp"

namespace mpdem {

// Point data: density, solid_fraction, number_density, velocity, momentum, stress,
// kinetic_stress, contact_stress (9 components, row-major: xx xy xz yx ...), temperature,
// coordination, boundary_force_density. An averaged axis has one point at its extent's centre
// and spacing = the extent. FieldData TimeValue.
void write_cg_vti(const std::filesystem::path& file, const CgGrid& grid, const CgFields& fields, double time,
                  VtkFormat format);

// The columns of a profile CSV along `axis` (0..2): time, the axis name, then the fields.
std::vector<std::string> cg_profile_columns(int axis);
// The rows of one profile output, one per point, in the columns' order.
std::vector<std::vector<double>> cg_profile_rows(const CgGrid& grid, const CgFields& fields, int axis, double time);

}  // namespace mpdem
