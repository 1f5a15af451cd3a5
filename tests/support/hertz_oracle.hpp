#pragma once
// Test oracle: the Hertz-Mindlin law (physics.md sections 5-6) written as separate single-law
// functions, straight from the equations, to check contact/contact_law.hpp's HertzLaw and
// evaluate_contact against. Not used by the engine.
//
// Sign convention: `overlap` is |delta| >= 0 (m); `normal_rate` is d(delta)/dt = (v_i - v_j) . n_ij
// (m/s), negative while approaching. f_n >= 0 acts on i along +n_ij.
#include <cmath>

#include "physics/hertz.hpp"
#include "physics/tangential.hpp"

namespace mpdem {

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
inline double normal_damping_coefficient(double xi_n, double m_star, double E_star, double r_star, double overlap) {
  return 2.0 * xi_n * std::sqrt(m_star * hertz_stiffness(E_star, r_star, overlap));
}

// k_t = 8 G* sqrt(r* |delta|)                                                (65)   [N/m]
inline double tangential_stiffness(double G_star, double r_star, double overlap) {
  return 8.0 * G_star * std::sqrt(r_star * overlap);
}

// d_t = 2 xi_t sqrt(m* k_t)                                                  (67)   [N s/m]
inline double tangential_damping_coefficient(double xi_t, double m_star, double k_t) {
  return 2.0 * xi_t * std::sqrt(m_star * k_t);
}

struct NormalForce {
  double magnitude = 0.0;         // N, f_n >= 0; force on i = magnitude * n_ij, on j the opposite
  double elastic = 0.0;           // N, Hertz part 4/3 E* sqrt(r*) |delta|^(3/2)
  double dissipated_power = 0.0;  // W, rate of mechanical energy removed (>= 0)
  bool clamped = false;           // true when the damped force would have been attractive
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

inline NormalForce normal_contact_force(double E_star, double r_star, double m_star, double xi_n, double overlap,
                                        double normal_rate) {
  if (overlap <= 0.0) return NormalForce{};
  return damped_normal_force(hertz_elastic_force(E_star, r_star, overlap),
                             normal_damping_coefficient(xi_n, m_star, E_star, r_star, overlap), normal_rate);
}

}  // namespace mpdem
