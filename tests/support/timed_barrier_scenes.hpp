#pragma once
// Scenes with barriers switched on and off in time ([[barriers]] active): a column of three
// spheres settled on a floor that is switched off at t = 0.5 s above an outlet (domain exit,
// particles removed), and a sphere drifting slowly onto a floor that is switched on at t = 0.2 s
// (so slowly that its own motion never rebuilds the lists). dt = 2^-14 s: the step times are
// exact binary fractions, so a step ends exactly at the switch.
#include <cmath>
#include <limits>
#include <string>

#include "barrier_mechanics_scene.hpp"

namespace mpdem::test {

inline constexpr double kTimedDt = 1.0 / 16384.0;  // s
inline constexpr double kLidOff = 0.5;             // s, the floor of lid_scene switches off
inline constexpr double kGateOn = 0.2;             // s, the floor of gate_scene switches on
inline constexpr double kGateGap = 2e-4;           // m, gate_scene's sphere above the floor at t = 0
inline constexpr double kGateSkin = 1e-3;          // m

// Horizontal square [-h, h]^2 in the plane z (normal +z): two triangles following `law`, at the
// fixed temperature T (K; NaN: insulated).
inline void add_timed_floor(Barriers& b, const std::string& group, double z, double h, const MotionLaw& law,
                            double T = std::numeric_limits<double>::quiet_NaN()) {
  const int g = b.group_index(group);
  const Vec3 p00{-h, -h, z}, p10{h, -h, z}, p11{h, h, z}, p01{-h, h, z};
  const auto id = static_cast<std::int64_t>(b.size());
  b.add(id, p00, p10, p11, g, kE, kNu, law, 0.0, T);
  b.add(id + 1, p00, p11, p01, g, kE, kNu, law, 0.0, T);
}

inline MotionLaw active_between(double from, double until) {
  MotionLaw law;
  law.active_from = from;
  law.active_until = until;
  return law;
}

// Three touching spheres stacked on the floor (active [0, kLidOff]), damped contacts; the domain
// ends 2 cm below the floor and removes what leaves it (the outlet).
inline Scene lid_scene(Integrator integ) {
  Scene s = base_scene(integ, kTimedDt, {0.0, 0.0, -kG});
  Params& prm = s.model.params;
  prm.contact.particle_particle.restitution = 0.5;
  prm.contact.particle_barrier.restitution = 0.5;
  prm.domain.bounded = true;
  prm.domain.min = {-0.05, -0.05, -0.02};
  prm.domain.max = {0.05, 0.05, 0.1};
  prm.domain.on_exit = ExitPolicy::Remove;
  add_timed_floor(s.barriers, "floor", 0.0, 0.02, active_between(0.0, kLidOff));
  for (int k = 0; k < 3; ++k) add_particle(s, k + 1, kR, {0.003, -0.004, kR * (1 + 2 * k)});
  return s;
}

// One sphere kGateGap above the plane of a floor (active [kGateOn, 1e9]), no gravity, drifting
// down to reach it at t = 0.25 s; the skin is such that the drift alone never rebuilds the lists.
inline Scene gate_scene(Integrator integ) {
  Scene s = base_scene(integ, kTimedDt, {0.0, 0.0, 0.0});
  s.model.params.neighbor.skin = kGateSkin;
  s.model.params.contact.particle_barrier.restitution = 0.5;
  add_timed_floor(s.barriers, "floor", 0.0, 0.02, active_between(kGateOn, 1e9));
  add_particle(s, 1, kR, {0.003, -0.004, kR + kGateGap}, {0.0, 0.0, -kGateGap / 0.25});
  return s;
}

}  // namespace mpdem::test
