#pragma once
// Near-field (non-contact) forces between two particles (physics.md section 4, thesis (44)-(46)).
// Pure, allocation-free functions; the pair loop in src/field/near_field_forces.cpp calls them.
//
// Sign convention: each law returns the scalar coefficient of n_ij = (x_i - x_j)/d; a positive
// value pushes i away from j (repulsion), and j gets the opposite force (Newton's third law).
// The potentials U(d) satisfy f = -dU/dd and vanish at infinity where that is possible; they
// feed the energy bookkeeping only.
#include <cmath>
#include <numbers>

namespace mpdem {

inline constexpr double kVacuumPermittivity = 8.8541878128e-12;  // F/m, eps0 (CODATA 2018)

// Coulomb constant of the medium 1 / (4 pi eps0 eps_r)   [N m^2 / C^2]
inline double coulomb_constant(double eps_r) { return 1.0 / (4.0 * std::numbers::pi * kVacuumPermittivity * eps_r); }

// Coulomb force coefficient q_i q_j / (4 pi eps0 eps_r d^2)                       (44)   [N]
// kc = coulomb_constant(eps_r); q in C, d > 0 in m.
inline double coulomb_force(double kc, double q_i, double q_j, double d) { return kc * q_i * q_j / (d * d); }

// Coulomb potential energy kc q_i q_j / d                                                [J]
inline double coulomb_potential(double kc, double q_i, double q_j, double d) { return kc * q_i * q_j / d; }

// Coefficients of the empirical law (46) for one pair of materials.
struct EmpiricalLaw {
  double a1 = 0.0;  // N m^b1, repulsive amplitude
  double b1 = 0.0;  // -, repulsive exponent
  double a2 = 0.0;  // N m^b2, attractive amplitude
  double b2 = 0.0;  // -, attractive exponent
};

// Empirical force coefficient a1 d^-b1 - a2 d^-b2                                  (46)   [N]
inline double empirical_force(const EmpiricalLaw& c, double d) {
  return c.a1 * std::pow(d, -c.b1) - c.a2 * std::pow(d, -c.b2);
}

// Antiderivative term of a d^-b: U = a d^(1-b) / (b - 1), or -a ln d for b = 1 (J).
inline double power_law_potential(double a, double b, double d) {
  if (a == 0.0) return 0.0;
  return b == 1.0 ? -a * std::log(d) : a * std::pow(d, 1.0 - b) / (b - 1.0);
}

// Potential of (46): U(d) with -dU/dd = a1 d^-b1 - a2 d^-b2                               [J]
inline double empirical_potential(const EmpiricalLaw& c, double d) {
  return power_law_potential(c.a1, c.b1, d) - power_law_potential(c.a2, c.b2, d);
}

}  // namespace mpdem
