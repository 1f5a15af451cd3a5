#pragma once
// Bonded test scenes (contact/bonds.hpp): spheres of r = 1 mm, density 2500 kg/m^3, bonds of
// lambda = 1 and E_b = 1 GPa made by the gap rule (docs/scene.md "[bonds]"), no gravity.
#include <cstdint>
#include <numbers>

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

// Adds n spheres of radius kBondR touching along +x from the origin (ids 1..n); the first fixed.
inline void add_chain(Scene& s, int n) {
  for (int k = 0; k < n; ++k) add_particle(s, k + 1, kBondR, {2.0 * kBondR * k, 0.0, 0.0});
  s.particles.fixed[0] = 1;
}

}  // namespace mpdem::test
