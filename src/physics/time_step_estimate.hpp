#pragma once
// Critical time-step estimates used by `mpdem check` and the run's start-up warning.
#include <cmath>
#include <numbers>

namespace mpdem {

// Rayleigh wave time of a sphere: pi R sqrt(rho/G) / (0.1631 nu + 0.8766)   [s]
inline double rayleigh_time(double radius, double density, double young, double poisson) {
  const double G = young / (2.0 * (1.0 + poisson));
  return std::numbers::pi * radius * std::sqrt(density / G) / (0.1631 * poisson + 0.8766);
}

// Duration of an elastic Hertz impact at normal speed v:
//   t_c = 2.943275 delta_max / v,  delta_max = (15 m* v^2 / (16 E* sqrt(r*)))^(2/5)   [s]
// (2.943275 = 2 integral_0^1 dx / sqrt(1 - x^(5/2)) = 0.8 B(2/5, 1/2), from energy
// conservation; equivalently t_c = 2.868266 (m*^2 / (r* E*^2 v))^(1/5)).
inline double hertz_contact_time(double m_eff, double E_eff, double r_eff, double v) {
  const double delta_max = std::pow(15.0 * m_eff * v * v / (16.0 * E_eff * std::sqrt(r_eff)), 0.4);
  return 2.9432751843247047 * delta_max / v;
}

}  // namespace mpdem
