#pragma once
// The parallel bond of Potyondy and Cundall (2004, Int. J. Rock Mech. Min. Sci. 41, 1329,
// section 2.2.2; docs/physics.md "Parallel bonds"): a cylinder of cement of radius R_b between
// two particles, as springs spread over its cross-section (normal stiffness k_n = E_b / L and
// shear stiffness k_s = k_n / kappa per unit area, Pa/m), that carries a normal force, a shear
// force, a twisting and a bending moment, each updated incrementally with the relative motion at
// the bond. It breaks when the largest tensile or shear stress on its rim reaches the strength.
#include <cmath>
#include <numbers>

#include "core/vec3.hpp"

namespace mpdem {

// The bond's cross-section: A = pi R^2 (m^2), I = pi R^4 / 4 (m^4), J = 2 I (m^4).
struct BondSection {
  double radius = 0.0;   // m, R_b
  double area = 0.0;     // m^2
  double inertia = 0.0;  // m^4, about a diameter
  double polar = 0.0;    // m^4, about the axis
};
inline BondSection bond_section(double radius) {
  const double a = std::numbers::pi * radius * radius;
  const double i = 0.25 * a * radius * radius;
  return {radius, a, i, 2.0 * i};
}

// The four springs of a bond of length L (m, the centre distance when it was made) with Young's
// modulus E_b (Pa) and stiffness ratio kappa = k_n / k_s: k_n A (N/m), k_s A (N/m), k_s J (N m/rad)
// and k_n I (N m/rad) (PC2004 eq. 9).
struct BondSprings {
  double normal = 0.0;  // N/m
  double shear = 0.0;   // N/m
  double twist = 0.0;   // N m/rad
  double bend = 0.0;    // N m/rad
};
inline BondSprings bond_springs(const BondSection& s, double length, double young, double stiffness_ratio) {
  const double kn = young / length;        // Pa/m
  const double ks = kn / stiffness_ratio;  // Pa/m
  return {kn * s.area, ks * s.area, ks * s.polar, kn * s.inertia};
}

// The largest tensile stress on the bond's rim, sigma_max = -F_n / A + |M_s| R / I, and the
// largest shear stress, tau_max = |F_s| / A + |M_n| R / J (PC2004 eq. 10), Pa. F_n > 0 in
// compression.
inline double bond_tensile_stress(const BondSection& s, double fn, const Vec3& ms) {
  return -fn / s.area + norm(ms) * s.radius / s.inertia;
}
inline double bond_shear_stress(const BondSection& s, const Vec3& fs, double mn) {
  return norm(fs) / s.area + std::abs(mn) * s.radius / s.polar;
}

// J, the energy the four linear springs hold.
inline double bond_energy(const BondSprings& k, double fn, const Vec3& fs, double mn, const Vec3& ms) {
  return 0.5 * (fn * fn / k.normal + dot(fs, fs) / k.shear + mn * mn / k.twist + dot(ms, ms) / k.bend);
}

// s, the bond's critical step: 2 / omega for the faster of its normal mode, sqrt(k_n A / m*),
// and its rotational one, sqrt((k_s A a^2 + k_n I) / I*) (the shear spring at the lever a, m,
// from a centre to the bond's centre, and the bending spring turning the reduced moment of
// inertia I*, kg m^2): the stability limit of central differences for one oscillator.
inline double bond_critical_step(const BondSprings& k, double reduced_mass, double reduced_inertia, double lever) {
  const double normal = k.normal / reduced_mass;                                // 1/s^2
  const double turning = (k.shear * lever * lever + k.bend) / reduced_inertia;  // 1/s^2
  return 2.0 / std::sqrt(normal > turning ? normal : turning);
}

// The reduced mass (kg) or moment of inertia (kg m^2) of a bond's two particles, a and b; one
// that cannot move (held) counts as infinitely heavy.
inline double bond_reduced(double a, double b, bool a_held, bool b_held) {
  if (a_held) return b;
  if (b_held) return a;
  return a * b / (a + b);
}

// The dashpot coefficient that damps a spring k between reduced inertia m to the ratio zeta of
// its critical damping: 2 zeta sqrt(m k).
inline double bond_dashpot(double zeta, double reduced, double spring) {
  return 2.0 * zeta * std::sqrt(reduced * spring);
}

}  // namespace mpdem
