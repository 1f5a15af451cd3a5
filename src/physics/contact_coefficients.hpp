#pragma once
// The overlap-dependent coefficients of one Hertz-Mindlin contact (physics.md sections 5-6),
// computed together so that they share one square root sqrt(r* |delta|): the pair loop's cost is
// dominated by square roots and divisions. Each field equals the single-law function named in
// its comment (physics/hertz.hpp, physics/tangential.hpp) up to rounding.
#include <cmath>

namespace mpdem {

struct ContactCoefficients {
  double k_n = 0.0;   // N/m, 2 E* sqrt(r* d)                  hertz_stiffness
  double f_el = 0.0;  // N, 4/3 E* sqrt(r*) d^(3/2) = 2/3 k_n d  (49), hertz_elastic_force
  double d_n = 0.0;   // N s/m, 2 xi_n sqrt(m* k_n)             (50), normal_damping_coefficient
  double k_t = 0.0;   // N/m, 8 G* sqrt(r* d)                   (65), tangential_stiffness
  double d_t = 0.0;   // N s/m, 2 xi_t sqrt(m* k_t)             (67), tangential_damping_coefficient
};

// The stiffnesses and the elastic force, which both forms below share: one sqrt(r* d).
inline ContactCoefficients elastic_coefficients(double E_star, double G_star, double r_star, double overlap) {
  ContactCoefficients c;
  const double root = std::sqrt(r_star * overlap);  // m
  c.k_n = 2.0 * E_star * root;
  c.f_el = (2.0 / 3.0) * c.k_n * overlap;
  c.k_t = 8.0 * G_star * root;
  return c;
}

// E_star, G_star (Pa), r_star (m), m_star (kg), damping ratios xi_n, xi_t (-), overlap d > 0 (m).
inline ContactCoefficients contact_coefficients(double E_star, double G_star, double r_star, double m_star,
                                                double xi_n, double xi_t, double overlap) {
  ContactCoefficients c = elastic_coefficients(E_star, G_star, r_star, overlap);
  c.d_n = 2.0 * xi_n * std::sqrt(m_star * c.k_n);
  c.d_t = xi_t > 0.0 ? 2.0 * xi_t * std::sqrt(m_star * c.k_t) : 0.0;  // no root when undamped
  return c;
}

// The same for a pair of materials whose E*, G* are known beforehand, with
// shear_root = sqrt(4 G*/E*) = sqrt(k_t/k_n): d_t = 2 xi_t sqrt(m* k_n) shear_root shares the
// normal damping's square root.
inline ContactCoefficients contact_coefficients_fixed_moduli(double E_star, double G_star, double shear_root,
                                                             double r_star, double m_star, double xi_n, double xi_t,
                                                             double overlap) {
  ContactCoefficients c = elastic_coefficients(E_star, G_star, r_star, overlap);
  const double mass_root = std::sqrt(m_star * c.k_n);  // sqrt(kg N/m)
  c.d_n = 2.0 * xi_n * mass_root;
  c.d_t = 2.0 * xi_t * mass_root * shear_root;
  return c;
}

// Elastic energy of the Hertz contact 8/15 E* sqrt(r*) d^(5/2) = 2/5 f_el d (section 12)   [J]
inline double hertz_energy_from_force(double f_el, double overlap) { return 0.4 * f_el * overlap; }

}  // namespace mpdem
