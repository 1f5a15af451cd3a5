#pragma once
// Scenes with inlets and sinks for the open-system tests (tests/sim/test_inlets.cpp,
// test_inlet_resume.cpp, test_sinks.cpp): an open box under gravity fed by an inlet box above it;
// and a bounded domain that removes what leaves it (test_run_record.cpp,
// test_interactions_open_system.cpp).
#include <cmath>
#include <cstdint>

#include "model/scene.hpp"
#include "contact_scenes.hpp"
#include "scene_builder.hpp"

namespace mpdem::test {

// Velocity Verlet, steps of dt (s), no particles yet; the domain [-0.1, 0.1]^2 x [-0.02, 0.1] m
// removes the particles that leave it.
inline Scene bounded_domain_scene(double dt) {
  Scene s = make_scene(dt, 1.0);
  s.model.params.time.integrator = Integrator::Verlet;
  DomainParams& d = s.model.params.domain;
  d.bounded = true;
  d.min = {-0.1, -0.1, -0.02};
  d.max = {0.1, 0.1, 0.1};
  d.on_exit = ExitPolicy::Remove;
  return s;
}

// An inlet filling the box [lo, hi] (m) with spheres of radius r (m) at mass_rate (kg/s).
inline InletSpec box_inlet(const Vec3& lo, const Vec3& hi, double r, double mass_rate) {
  InletSpec in;
  in.name = "feed";
  in.volume.region.shape = RegionShape::Box;
  in.volume.region.min = lo;
  in.volume.region.max = hi;
  in.radius.value = r;
  in.mass_rate = mass_rate;
  in.interval = 1e-3;
  in.seed = 7;
  return in;
}

// A 0.02 m open box (soft walls, friction) under gravity, dt = 2e-5 s, no particles yet; the
// inlet box 0.004 < x, y < 0.016, 0.006 < z < 0.016 above its floor.
inline Scene fed_box_scene(double duration, double mass_rate) {
  Scene s = make_scene(2e-5, duration);
  Params& prm = s.model.params;
  prm.time.integrator = Integrator::Verlet;
  prm.fields.gravity = {0.0, 0.0, -9.81};
  prm.neighbor.skin = 2e-4;
  prm.checks.max_overlap = 0.2;
  ContactLawParams& c = prm.contact.particle_particle;
  c.restitution = 0.5;
  c.mu_static = 0.5;
  c.mu_dynamic = 0.4;
  prm.contact.particle_barrier = c;
  set_material(s, 2500.0, 1e6, 0.3);
  add_open_box(s.barriers, 0.02, 0.02, 2, 1e6, 0.3);
  prm.inlets.push_back(box_inlet({0.004, 0.004, 0.006}, {0.016, 0.016, 0.016}, 0.001, mass_rate));
  return s;
}

}  // namespace mpdem::test
