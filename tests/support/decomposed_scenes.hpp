#pragma once
// Scenes run over several ranks (tests/parallel): a frictional, rolling, thermal cluster in a box
// of barriers that the bricks cut (also with charges and the near field, or without rolling
// resistance), and a column that falls through the cuts.
#include "support/dense_granular_scene.hpp"

namespace mpdem::test {

// 6 x 6 x 5 spheres (r = 1-1.05 mm) in a 12.7 mm open box, random velocities (0.15 m/s) and
// spins, gravity; friction, rolling resistance (mu_r = 0.05), conduction at 290-310 K.
inline Scene cluster(Integrator integ, double dt) {
  Scene s = dense_scene(6, 6, 5, 1e-3, 0.05, 2.12e-3, 0.15, 5, dt);
  s.model.params.time.integrator = integ;
  s.model.params.analysis.thermal = true;
  for (ContactLawParams* c : {&s.model.params.contact.particle_particle, &s.model.params.contact.particle_barrier})
    c->mu_rolling = 0.05;
  for (std::size_t i = 0; i < s.particles.size(); ++i)
    s.particles.T[i] = 290.0 + static_cast<double>(s.particles.id[i] % 21);
  return s;
}

// A column of 4 x 4 x 12 spheres (0.3 mm apart) in a 9.2 mm open box, falling at 0.3 m/s onto
// the floor under gravity: the bricks cut it across its height and the spheres fall through the
// cuts. Friction, rolling resistance and conduction.
inline Scene column(Integrator integ, double dt) {
  Scene s = dense_scene(4, 4, 12, 1e-3, 0.05, 2.3e-3, 0.02, 5, dt);
  s.model.params.time.integrator = integ;
  for (ContactLawParams* c : {&s.model.params.contact.particle_particle, &s.model.params.contact.particle_barrier})
    c->mu_rolling = 0.05;
  for (std::size_t i = 0; i < s.particles.size(); ++i) s.particles.v[i].z -= 0.3;
  s.model.params.analysis.thermal = true;
  for (std::size_t i = 0; i < s.particles.size(); ++i)
    s.particles.T[i] = 290.0 + static_cast<double>(s.particles.id[i] % 21);
  return s;
}

// The cluster without rolling resistance and with mu_s = 0.5 > mu_d = 0.4: the tangential force
// jumps at the stick/slip decisions.
inline Scene sliding_cluster(Integrator integ, double dt) {
  Scene s = cluster(integ, dt);
  for (ContactLawParams* c : {&s.model.params.contact.particle_particle, &s.model.params.contact.particle_barrier}) {
    c->mu_rolling = 0.0;
    c->mu_static = 0.5;
    c->mu_dynamic = 0.4;
  }
  return s;
}

// The cluster with charged spheres (+-0.2 nC by id, Coulomb's law (44) within 3 mm, about the
// spacing of next neighbours): the near field acts across the cuts, on ghosts.
inline Scene charged_cluster(Integrator integ, double dt) {
  Scene s = cluster(integ, dt);
  NearFieldParams& nf = s.model.params.near_field;
  nf.coulomb = true;
  nf.cutoff = 3e-3;
  for (std::size_t i = 0; i < s.particles.size(); ++i) s.particles.charge[i] = s.particles.id[i] % 2 ? 2e-10 : -2e-10;
  return s;
}

}  // namespace mpdem::test
