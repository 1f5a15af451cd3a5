#pragma once
// Common setup of the contact mechanics tests (particle-particle and particle-barrier): the particles' material and
// size, gravity, the sphere mass and E* against a barrier, and a base scene (integrator, time step, gravity,
// tolerances).
#include <cmath>

#include "contact_scenes.hpp"
#include "model/params.hpp"
#include "model/scene.hpp"
#include "scene_builder.hpp"

namespace mpdem::test {

inline constexpr double kRho = 2500.0;  // kg/m^3
inline constexpr double kE = 1e7;       // Pa
inline constexpr double kNu = 0.3;      // -
inline constexpr double kR = 0.005;     // m
inline constexpr double kG = 9.81;      // m/s^2
inline const double kPi = std::acos(-1.0);

inline double sphere_mass(double R) { return 4.0 / 3.0 * kPi * R * R * R * kRho; }
// (51) with the barrier's own modulus, written out independently of the engine   [Pa]
inline double E_star(double Eb, double nub) { return kE * Eb / (Eb * (1.0 - kNu * kNu) + kE * (1.0 - nub * nub)); }
inline const char* name(Integrator i) { return i == Integrator::Verlet ? "verlet" : "trapezoidal"; }

inline Scene base_scene(Integrator integ, double dt, const Vec3& gravity) {
  Scene s = test::make_scene(dt, 1.0);
  s.model.params.time.integrator = integ;
  s.model.params.time.phi = 0.5;
  s.model.params.fields.gravity = gravity;
  s.model.params.tolerance.position = 1e-10;
  s.model.params.tolerance.velocity = 1e-10;
  test::set_material(s, kRho, kE, kNu);
  // These tests check the laws at finite overlaps: the overlap instability check would stop
  // them; it is tested in test_instability.cpp.
  s.model.params.checks.max_overlap = 0.0;
  return s;
}

}  // namespace mpdem::test
