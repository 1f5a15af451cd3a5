#pragma once
// A named material: the defaults a particle (or barrier) takes for every property its input
// file does not give.
#include <cmath>
#include <limits>
#include <string>

namespace mpdem {

struct Material {
  std::string name;
  double density = 2500.0;       // kg/m^3
  double young = 1e7;            // Pa (kRigidYoung: a rigid barrier material)
  double poisson = 0.3;          // - in [0, 0.5)
  double conductivity = 1.0;     // W/(m K)
  double heat_capacity = 800.0;  // J/(kg K)
  double emissivity = 0.9;       // - in [0, 1]
  double charge = 0.0;           // C, default particle charge
  double temperature = 293.15;   // K, default initial particle temperature
  // A copy of another material with the per-particle or per-element values a particle or barrier
  // CSV gave (model/material_variants.hpp): its index, or -1 for a material of the scene.
  int variant_of = -1;
};

// Young's modulus of a rigid barrier ([[barriers]] rigid = true)   [Pa]. An infinitely stiff
// element adds no compliance to (51), so the particle's E and nu alone set the contact; a
// material with it is made for barrier elements only (particle moduli are finite).
inline constexpr double kRigidYoung = std::numeric_limits<double>::infinity();

inline bool is_rigid(const Material& m) { return std::isinf(m.young); }

}  // namespace mpdem
