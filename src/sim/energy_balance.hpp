#pragma once
// Energy bookkeeping of the particles (physics.md section 12): kinetic 1/2 m v^2, rotational
// 1/2 j w^2, gravitational -m g.x. Sums are thread-count independent.
#include "model/params.hpp"
#include "state/particles.hpp"

namespace mpdem {

struct ParticleEnergy {
  double kinetic = 0.0;     // J
  double rotational = 0.0;  // J
  double potential = 0.0;   // J, gravitational, zero at the origin
};

ParticleEnergy particle_energy(const Particles& p, const Vec3& gravity);

}  // namespace mpdem
