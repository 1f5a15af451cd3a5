#pragma once
// Effective moduli of a particle (E_i, nu_i) against a barrier element (E_b, nu_b), physics.md
// section 7: (51) and Mindlin's G* with the element's own constants, or, for a rigid element
// (E_b = +inf, [[barriers]] rigid = true), their limits E_i/(1 - nu_i^2) and G_i/(2 - nu_i),
// which the finite formulas cannot give (they evaluate inf/inf).
#include <cmath>

#include "physics/hertz.hpp"
#include "physics/tangential.hpp"

namespace mpdem {

// E* of a particle against a barrier element   [Pa]
inline double barrier_effective_modulus(double E_i, double nu_i, double E_b, double nu_b) {
  return std::isinf(E_b) ? effective_modulus_rigid(E_i, nu_i) : effective_modulus(E_i, nu_i, E_b, nu_b);
}

// G* (Mindlin, no slip) of a particle against a barrier element   [Pa]
inline double barrier_effective_shear_modulus(double E_i, double nu_i, double E_b, double nu_b) {
  const double G_i = shear_modulus(E_i, nu_i);
  return std::isinf(E_b) ? effective_shear_modulus_rigid(G_i, nu_i)
                         : effective_shear_modulus(G_i, nu_i, shear_modulus(E_b, nu_b), nu_b);
}

}  // namespace mpdem
