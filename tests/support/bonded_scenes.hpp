#pragma once
// Bonded test scenes (contact/bonds.hpp): spheres of r = 1 mm, density 2500 kg/m^3, bonds of
// lambda = 1 and E_b = 1 GPa made by the gap rule (docs/scene.md "[bonds]"), no gravity.
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "model/scene.hpp"
#include "support/contact_scenes.hpp"
#include "support/scene_builder.hpp"

namespace mpdem::test {

inline constexpr double kBondR = 1e-3;                                   // m, sphere radius
inline constexpr double kBondRho = 2500.0;                               // kg/m^3
inline constexpr double kBondE = 1e9;                                    // Pa, E_b
inline constexpr double kBondArea = std::numbers::pi * kBondR * kBondR;  // m^2, A (lambda = 1)
inline constexpr double kBondI = 0.25 * kBondArea * kBondR * kBondR;     // m^4, I
inline constexpr double kBondJ = 2.0 * kBondI;                           // m^4, J

// A scene with bonds made between particles less than `gap` apart (surface to surface), with
// the bond damping ratio zeta and the viscous drag c (N s/m) on every free particle.
inline Scene bonded_scene(double dt, Integrator integ, double zeta, double drag, double gap = 1e-6) {
  Scene s = make_scene(dt, 10.0);
  s.model.params.time.integrator = integ;
  s.model.params.fields.gravity = {};
  s.model.params.fields.drag = drag;
  set_material(s, kBondRho, 1e8, 0.3);
  BondKeys k;
  k.young = kBondE;
  k.radius_ratio = 1.0;
  k.damping = zeta;
  k.gap = gap;
  s.model.params.bonds.defaults = k;
  return s;
}

// m, the static tip deflection of a chain of n bonds of length l = 2 kBondR (E_b = kBondE,
// lambda = 1, k_n/k_s = kappa), the first sphere fixed, under a tip load f (N) across it
// (docs/physics.md section 22): f l^3 n (4 n^2 - 1) / (12 E I) + n kappa f l / (E A).
inline double chain_tip_deflection(int n, double f, double kappa) {
  const double l = 2.0 * kBondR, m = n;
  return f * l * l * l * m * (4.0 * m * m - 1.0) / (12.0 * kBondE * kBondI) + m * kappa * f * l / (kBondE * kBondArea);
}

// Adds n spheres of radius kBondR touching along +x from the origin (ids 1..n); the first fixed.
inline void add_chain(Scene& s, int n) {
  for (int k = 0; k < n; ++k) add_particle(s, k + 1, kBondR, {2.0 * kBondR * k, 0.0, 0.0});
  s.particles.fixed[0] = 1;
}

// A block of side^3 spheres of radii 0.9..1 R (random, seed 11) on a lattice of 2 R, bonded to
// their lattice neighbours (gap 0.3 mm; E_b = 1e8 Pa, strengths 2e5 Pa, zeta 0.1), falling at
// 3 m/s and turning onto a plate just below, under gravity: bonds break near the plate within
// 2e-4 s. ids 1..n in lattice order, or relabelled n..1 (particle added in reverse order).
inline Scene bonded_block(Integrator integ, double dt, int side, bool relabel = false) {
  Scene s = bonded_scene(dt, integ, 0.1, 0.0, 0.3e-3);
  s.model.params.checks.max_overlap = 0.0;
  s.model.params.fields.gravity = {0.0, 0.0, -9.81};
  BondKeys& k = *s.model.params.bonds.defaults;
  k.young = 1e8;
  k.tensile_strength = 2e5;
  k.shear_strength = 2e5;
  const double W = 2.0 * kBondR * side;
  add_flat_square(s.barriers, "plate", {0.5 * W, 0.5 * W, 0.0}, 2.0 * W, 4, 1e8, 0.3);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(0.9, 1.0);
  struct P {
    Vec3 x;
    double r;
  };
  std::vector<P> ps;
  for (int a = 0; a < side; ++a)
    for (int b = 0; b < side; ++b)
      for (int c = 0; c < side; ++c)
        ps.push_back({{2.0 * kBondR * (a + 0.5), 2.0 * kBondR * (b + 0.5), 2.0 * kBondR * (c + 0.5) + 0.01e-3},
                      kBondR * U(rng)});
  const std::size_t n = ps.size();
  for (std::size_t k2 = 0; k2 < n; ++k2) {
    const std::size_t at = relabel ? n - 1 - k2 : k2;
    add_particle(s, static_cast<std::int64_t>(relabel ? k2 + 1 : at + 1), ps[at].r, ps[at].x, {0.3, 0.0, -3.0},
                 {0.0, 3.0, 0.0});
  }
  return s;
}

}  // namespace mpdem::test
