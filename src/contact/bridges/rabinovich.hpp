#pragma once
// Rabinovich, Esayanur & Moudgil (2005), Langmuir 21, 10992: the capillary force of a bridge of
// fixed volume V between two spheres at surface gap S,
//   F = 2 pi R gamma cos(theta) / (1 + S / (2 d_sp)) + 2 pi R gamma sin(alpha) sin(theta + alpha),
//   d_sp = (S/2) (-1 + sqrt(1 + 2V / (pi R S^2))),   alpha = sqrt(2 d_sp / R),
// d_sp the immersion distance of each surface in the liquid, alpha the half-filling angle, R the
// harmonic mean radius 2 R_i R_j / (R_i + R_j) as in Willett's form (a sphere on a plane: 2 R).
// With c = 2V / (pi R): d_sp = (sqrt(S^2 + c) - S) / 2 (written c / (2 (sqrt(S^2 + c) + S)),
// free of cancellation at large S) and the first term is 2 pi R gamma cos(theta) (1 - S / sqrt(S^2 + c)).
// At S = 0 the first term is 2 pi R gamma cos(theta), Willett's value; the second adds the
// contact line's pull at the half-filling angle alpha_0 = (c / R^2)^(1/4) (the paper's "surface
// tension" term), both falling with the gap.
// Energy (the work to open the gap from 0 to S): the first term in closed form,
// 2 pi R gamma cos(theta) (sqrt(c) - 2 d_sp); the second by 12-point Gauss-Legendre quadrature in
// t = asinh(S / sqrt(c)), where d_sp = sqrt(c) e^(-t) / 2 and alpha = alpha_0 e^(-t/2): the
// integrand sin(alpha) sin(theta + alpha) sqrt(c) cosh(t) is smooth on [0, asinh(S_c / sqrt(c))]
// (relative error below 1e-12 there, tests/contact/test_bridge_law.cpp).
#include <array>
#include <cstddef>
#include <cmath>
#include <numbers>

namespace mpdem {

namespace rabinovich {
// The positive nodes and their weights of the 12-point Gauss-Legendre rule on [-1, 1].
inline constexpr std::array<double, 6> kNodes{0.98156063424671924, 0.9041172563704748,  0.76990267419430469,
                                              0.58731795428661748, 0.36783149899818018, 0.12523340851146894};
inline constexpr std::array<double, 6> kWeights{0.047175336386511835, 0.10693932599531857, 0.16007832854334633,
                                                0.20316742672306584,  0.23349253653835478, 0.24914704581340288};
}  // namespace rabinovich

// The bridge's geometry: R (m, harmonic mean radius), gamma (N/m), theta (rad), V (m^3).
struct RabinovichBridge {
  double R, gamma, theta, V;
  double c() const { return 2.0 * V / (std::numbers::pi * R); }  // m^2
};

// N, the force's magnitude at gap S >= 0 (m).
inline double rabinovich_force(const RabinovichBridge& b, double S) {
  const double c = b.c(), root = std::sqrt(S * S + c);
  const double d_sp = 0.5 * c / (root + S);
  const double alpha = std::sqrt(2.0 * d_sp / b.R);
  const double two_pi_r_gamma = 2.0 * std::numbers::pi * b.R * b.gamma;
  return two_pi_r_gamma * (std::cos(b.theta) * (1.0 - S / root) + std::sin(alpha) * std::sin(b.theta + alpha));
}

// J, the integral of rabinovich_force over [0, S].
inline double rabinovich_energy(const RabinovichBridge& b, double S) {
  using namespace rabinovich;
  const double c = b.c(), sc = std::sqrt(c), root = std::sqrt(S * S + c);
  const double d_sp = 0.5 * c / (root + S);
  const double two_pi_r_gamma = 2.0 * std::numbers::pi * b.R * b.gamma;
  const double pressure = std::cos(b.theta) * (sc - 2.0 * d_sp);
  // The contact line's term over t in [0, T]: nodes at T/2 (1 -+ x).
  // sin(theta + alpha) = sin(theta) cos(alpha) + cos(theta) sin(alpha); cosh(t) = (w^-2 + w^2) / 2
  // with w = e^(-t/2): one exponential, sine and cosine per node.
  const double T = std::asinh(S / sc), half = 0.5 * T, alpha0 = std::sqrt(sc / b.R);
  const double sin_t = std::sin(b.theta), cos_t = std::cos(b.theta);
  double line = 0.0;
  for (std::size_t k = 0; k < kNodes.size(); ++k)
    for (const double t : {half * (1.0 - kNodes[k]), half * (1.0 + kNodes[k])}) {
      const double w = std::exp(-0.5 * t), alpha = alpha0 * w, sa = std::sin(alpha), ca = std::cos(alpha);
      line += kWeights[k] * sa * (sin_t * ca + cos_t * sa) * 0.5 * (1.0 / (w * w) + w * w);
    }
  return two_pi_r_gamma * (pressure + sc * half * line);
}

}  // namespace mpdem
