#pragma once
// The shape error of a clump template: its mass properties against those of the solid it
// approximates (`mpdem clump`, docs/tools.md "mpdem clump"). All per unit density.
#include <array>
#include <string>

#include "geometry/mesh_mass.hpp"
#include "physics/clump_mass.hpp"

namespace mpdem {

struct ShapeError {
  double volume = 0.0;                // (V_template - V_solid) / V_solid
  double centroid = 0.0;              // |c_template - c_solid| / V_solid^(1/3): the offset over the solid's size
  std::array<double, 3> principal{};  // (I_k,template - I_k,solid) / I_k,solid, moments ascending
};

ShapeError shape_error(const MeshMassProperties& solid, const ClumpMassProperties& tpl);

// The table `mpdem clump` prints: a row per quantity (volume, centroid x, y, z, I1, I2, I3) with
// the solid's exact value, the template's and the relative error; values with 12 significant
// digits, so the exact ones can be compared with closed forms.
std::string shape_error_table(const MeshMassProperties& solid, const ClumpMassProperties& tpl);

}  // namespace mpdem
