#pragma once
// Willett et al. (2000), Langmuir 16, 9396, eq. 16 in the form for unequal spheres: the capillary
// force of a pendular bridge of volume V at surface gap S,
//   F = 2 pi R gamma cos(theta) / (1 + 1.05 S^ + 2.5 S^^2),  S^ = S sqrt(R / V),
// R = 2 R_i R_j / (R_i + R_j) (the harmonic mean radius: R for equal spheres, 2 R for a sphere on
// a plane). For equal spheres of radius R it is the paper's 1 / (1 + 2.1 s + 10 s^2) with
// s = (S/2) sqrt(R/V). The energy is the work to open the gap from 0 to S, in closed form (the
// quadratic 2.5 x^2 + 1.05 x + 1 has no real root, so its integral is an arctangent).
#include <cmath>

namespace mpdem {

namespace willett {
inline constexpr double kB = 1.05, kC = 2.5;  // the paper's coefficients of S^ and S^^2
// sqrt(4 kC - kB^2) = sqrt(8.8975): the root of the quadratic's negative discriminant (the test checks it)
inline constexpr double kRootD = 2.982867747654931;
}  // namespace willett

// N, the force's magnitude at gap S >= 0 (m); f0 = 2 pi R gamma cos(theta) (N), k = sqrt(R / V) (m^-1).
inline double willett_force(double f0, double k, double S) {
  const double x = k * S;
  return f0 / (1.0 + x * (willett::kB + willett::kC * x));
}

// J, the integral of willett_force over [0, S]:
//   (f0 / k) (2 / sqrt(D)) [atan((2 c x + b) / sqrt(D)) - atan(b / sqrt(D))],  D = 4c - b^2,
// the difference of the arctangents taken as one (both arguments are positive).
inline double willett_energy(double f0, double k, double S) {
  using namespace willett;
  const double x = k * S;
  const double u0 = kB / kRootD, u = (2.0 * kC * x + kB) / kRootD;
  return 2.0 * f0 / (k * kRootD) * std::atan((u - u0) / (1.0 + u * u0));
}

}  // namespace mpdem
