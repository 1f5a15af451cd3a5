#pragma once
// Critical time-step and impact estimates used by `mpdem check` and the run's start-up warning.
#include <cmath>
#include <numbers>

namespace mpdem {

// Rayleigh wave time of a sphere: pi R sqrt(rho/G) / (0.1631 nu + 0.8766)   [s]
inline double rayleigh_time(double radius, double density, double young, double poisson) {
  const double G = young / (2.0 * (1.0 + poisson));
  return std::numbers::pi * radius * std::sqrt(density / G) / (0.1631 * poisson + 0.8766);
}

// Largest overlap of an undamped Hertz impact at normal speed v, from energy conservation
// (1/2 m* v^2 = 8/15 E* sqrt(r*) delta^(5/2)):
//   delta_max = (15 m* v^2 / (16 E* sqrt(r*)))^(2/5)   [m]
inline double hertz_peak_overlap(double m_eff, double E_eff, double r_eff, double v) {
  return std::pow(15.0 * m_eff * v * v / (16.0 * E_eff * std::sqrt(r_eff)), 0.4);
}

// Largest overlap of an undamped linear-spring impact (stiffness k, N/m) at speed v:
//   delta_max = v sqrt(m* / k)   [m]
inline double linear_peak_overlap(double m_eff, double k, double v) { return v * std::sqrt(m_eff / k); }

// Duration of an undamped linear-spring impact (stiffness k, N/m; any speed):
//   t_c = pi sqrt(m* / k)   [s]   (damping lengthens it by 1/sqrt(1 - xi^2))
inline double linear_contact_time(double m_eff, double k) { return std::numbers::pi * std::sqrt(m_eff / k); }

// Duration of an elastic Hertz impact at normal speed v:
//   t_c = 2.943275 delta_max / v   [s]
// (2.943275 = 2 integral_0^1 dx / sqrt(1 - x^(5/2)) = 0.8 B(2/5, 1/2), from energy
// conservation; equivalently t_c = 2.868266 (m*^2 / (r* E*^2 v))^(1/5)).
inline double hertz_contact_time(double m_eff, double E_eff, double r_eff, double v) {
  return 2.9432751843247047 * hertz_peak_overlap(m_eff, E_eff, r_eff, v) / v;
}

// Largest stable step of the central-difference (Verlet) scheme on an undamped spring of
// stiffness k (N/m) between two masses of reduced mass m* (2 / omega, omega = sqrt(k / m*)):
//   dt_c = 2 sqrt(m* / k)   [s]
// (a parallel bond's normal spring: k = k_n A = E_b A / L, docs/physics.md "Parallel bonds").
inline double spring_critical_step(double m_eff, double k) { return 2.0 * std::sqrt(m_eff / k); }

}  // namespace mpdem
