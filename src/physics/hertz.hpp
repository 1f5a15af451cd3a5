#pragma once
// Hertz normal contact with nonlinear viscous damping (physics.md section 5, thesis (49)-(56)).
// Pure, allocation-free functions; the pair loop calls them per contact.
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

// Elastic Hertz force 4/3 E* sqrt(r*) |delta|^(3/2), the first term of (49)   [N]
inline double hertz_elastic_force(double E_star, double r_star, double overlap) {
  return (4.0 / 3.0) * E_star * std::sqrt(r_star) * overlap * std::sqrt(overlap);
}

// Tangent normal stiffness k_n = dF/d|delta| = 2 E* sqrt(r* |delta|)   [N/m]
inline double hertz_stiffness(double E_star, double r_star, double overlap) {
  return 2.0 * E_star * std::sqrt(r_star * overlap);
}

// Elastic energy stored in the contact, 8/15 E* sqrt(r*) |delta|^(5/2) (section 12)   [J]
inline double hertz_elastic_energy(double E_star, double r_star, double overlap) {
  return (8.0 / 15.0) * E_star * std::sqrt(r_star) * overlap * overlap * std::sqrt(overlap);
}

// Normal damping coefficient d* = 2 xi_n sqrt(2 m* E* sqrt(r* |delta|)) = 2 xi_n sqrt(m* k_n)  (50)
// [N s/m]. xi_n: the damping ratio, either given by the user or from
// damping_ratio_for_restitution(e) (physics/restitution.hpp, the Departure of section 5).
inline double normal_damping_coefficient(double xi_n, double m_star, double E_star, double r_star,
                                         double overlap) {
  return 2.0 * xi_n * std::sqrt(m_star * hertz_stiffness(E_star, r_star, overlap));
}

// The thesis's damping ratio for a restitution e, derived for a LINEAR spring-dashpot     (55)
// xi = -ln(e) / sqrt(pi^2 + ln(e)^2). Kept only to document why the Departure exists: fed into
// (50) it rebounds with less than e. Use damping_ratio_for_restitution() instead.
inline double thesis_damping_ratio(double e) {
  const double l = std::log(e);
  return -l / std::sqrt(std::numbers::pi * std::numbers::pi + l * l);
}

struct NormalForce {
  double magnitude = 0.0;          // N, f_n >= 0; force on i = magnitude * n_ij, on j the opposite
  double elastic = 0.0;            // N, Hertz part 4/3 E* sqrt(r*) |delta|^(3/2)
  double dissipated_power = 0.0;   // W, rate of mechanical energy removed (>= 0)
  bool clamped = false;            // true when the damped force would have been attractive
};

// Net normal force (49) with the damping (50), clamped at zero so it is never attractive.
// normal_rate = (v_i - v_j).n_ij (m/s, negative approaching).
// Dissipation: the pair's mechanical energy changes at f_n * normal_rate (kinetic) plus
// -F_el * normal_rate (elastic, since d|delta|/dt = -normal_rate), so the power removed is
// (F_el - f_n) * normal_rate: = d* rate^2 unclamped, = F_el * rate when clamped (the elastic
// energy left at separation is released without doing work).
// The same from the elastic force f_el (N) and damping coefficient d* (N s/m) of the overlap.
inline NormalForce damped_normal_force(double f_el, double d_star, double normal_rate) {
  NormalForce out;
  out.elastic = f_el;
  const double f = f_el - d_star * normal_rate;
  out.clamped = f < 0.0;
  out.magnitude = out.clamped ? 0.0 : f;
  out.dissipated_power = (out.elastic - out.magnitude) * normal_rate;
  return out;
}

inline NormalForce normal_contact_force(double E_star, double r_star, double m_star, double xi_n,
                                        double overlap, double normal_rate) {
  if (overlap <= 0.0) return NormalForce{};
  return damped_normal_force(hertz_elastic_force(E_star, r_star, overlap),
                             normal_damping_coefficient(xi_n, m_star, E_star, r_star, overlap), normal_rate);
}

}  // namespace mpdem
