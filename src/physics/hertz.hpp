#pragma once
// Effective properties of a contact pair (physics.md section 5, thesis (51)-(53), (55)), from
// which the contact tables (contact/contact_table.hpp) are built. The Hertz law itself is
// contact/contact_law.hpp's HertzLaw; tests/support/hertz_oracle.hpp keeps it as single-law
// functions to check it against.
//
// Sign convention: `overlap` is |delta| >= 0 (m), where delta = |x_i - x_j| - (R_i + R_j) < 0 in
// contact; `normal_rate` is d(delta)/dt = (v_i - v_j) . n_ij (m/s), negative while approaching.
// The scalar normal force f_n >= 0 acts on i along +n_ij (pushing i away from j), on j along -n_ij.
#include <cmath>
#include <numbers>

namespace mpdem {

// E* = E_i E_j / (E_j (1 - nu_i^2) + E_i (1 - nu_j^2))                       (51)   [Pa]
// Also the particle-barrier value with the barrier's own E, nu (76)-(79).
inline double effective_modulus(double E_i, double nu_i, double E_j, double nu_j) {
  return E_i * E_j / (E_j * (1.0 - nu_i * nu_i) + E_i * (1.0 - nu_j * nu_j));
}

// Infinitely stiff barrier (E_j -> infinity in (51)): E* = E_i / (1 - nu_i^2)   [Pa]
inline double effective_modulus_rigid(double E_i, double nu_i) { return E_i / (1.0 - nu_i * nu_i); }

// r* = R_i R_j / (R_i + R_j)                                                  (52)   [m]
// (particle-barrier: r* = R_i, (76)-(79))
inline double effective_radius(double R_i, double R_j) { return R_i * R_j / (R_i + R_j); }

// m* = m_i m_j / (m_i + m_j)                                                  (53)   [kg]
// (particle-barrier: m* = m_i)
inline double effective_mass(double m_i, double m_j) { return m_i * m_j / (m_i + m_j); }

// The thesis's damping ratio for a restitution e, derived for a LINEAR spring-dashpot     (55)
// xi = -ln(e) / sqrt(pi^2 + ln(e)^2). Kept only to document why the Departure exists: fed into
// (50) it rebounds with less than e. Use damping_ratio_for_restitution() instead.
inline double thesis_damping_ratio(double e) {
  const double l = std::log(e);
  return -l / std::sqrt(std::numbers::pi * std::numbers::pi + l * l);
}

}  // namespace mpdem
