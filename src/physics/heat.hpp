#pragma once
// Heat flow laws of the lumped thermal model (physics.md section 8, thesis (80)-(96)).
// Pure, allocation-free functions. Every heat flow is the power INTO particle i (W): positive
// when i warms up. Temperatures in K.
#include <algorithm>
#include <cmath>
#include <numbers>

namespace mpdem {

inline constexpr double kStefanBoltzmann = 5.670374419e-8;  // W/(m^2 K^4), sigma (94)

// Distance from centre i to the plane of the contact lens, x_c = (d^2 + R_i^2 - R_j^2)/(2d) (88)  [m]
inline double contact_plane_distance(double d, double R_i, double R_j) {
  return (d * d + R_i * R_i - R_j * R_j) / (2.0 * d);
}

// Contact (lens) area of two overlapping spheres A = pi (R_i^2 - x_c^2)                  (89)  [m^2]
// Symmetric in i, j; zero when the spheres do not overlap (clamped against round-off).
inline double contact_area_pair(double d, double R_i, double R_j) {
  const double xc = contact_plane_distance(d, R_i, R_j);
  return std::numbers::pi * std::max(0.0, R_i * R_i - xc * xc);
}

// Conductivity of a pair, the harmonic mean K = 2 k_i k_j / (k_i + k_j)          [W/(m K)]
// (two insulators give 0, not 0/0)
inline double pair_conductivity(double k_i, double k_j) {
  const double s = k_i + k_j;
  return s > 0.0 ? 2.0 * k_i * k_j / s : 0.0;
}

// Conduction into i from j across their contact: K A (T_j - T_i) / d                (88), (90)  [W]
inline double conduction_heat(double K, double A, double d, double T_i, double T_j) { return K * A * (T_j - T_i) / d; }

// Contact area of a sphere of radius R cut by a plane at depth `overlap`:
// A = pi (R^2 - (R - overlap)^2); a centre past the plane gives the full disc pi R^2.     [m^2]
inline double contact_area_plane(double R, double overlap) {
  const double h = std::max(0.0, R - std::clamp(overlap, 0.0, R));
  return std::numbers::pi * (R * R - h * h);
}

// Relative air speed range where the fit (93) holds (it peaks at 25 m/s, then falls).
inline constexpr double kConvectionMaxSpeed = 20.0;  // m/s

// Convective heat transfer coefficient h(v) = 12.15335 - 1.1630 v + 11.630 sqrt(v)   (93)  [W/(m^2 K)]
// v = |v_i - v_air| (m/s), clamped to [0, 20] m/s, the range of the fit.
inline double convection_coefficient(double v) {
  const double s = std::clamp(v, 0.0, kConvectionMaxSpeed);
  return 12.15335 - 1.1630 * s + 11.630 * std::sqrt(s);
}

// Surface area of a sphere A_s = 4 pi R^2                                                   [m^2]
inline double sphere_area(double R) { return 4.0 * std::numbers::pi * R * R; }

// Newton's law of cooling h A_s (T_air - T_i)                                       (91)  [W]
inline double convection_heat(double h, double R, double T_air, double T_i) {
  return h * sphere_area(R) * (T_air - T_i);
}

// Grey-body radiation exchange eps sigma A_s (T_env^4 - T_i^4)                  (94)-(95)  [W]
inline double radiation_heat(double emissivity, double R, double T_env, double T_i) {
  const double e2 = T_env * T_env, t2 = T_i * T_i;
  return emissivity * kStefanBoltzmann * sphere_area(R) * (e2 * e2 - t2 * t2);
}

}  // namespace mpdem
