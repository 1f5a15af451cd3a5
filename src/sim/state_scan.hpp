#pragma once
// One pass over the particles after every step for the run's health checks (design.md,
// reliability): energies for the energy balance, non-finite states, particles outside the
// domain. Counting only - the caller looks for the culprits in the rare case there are any.
// Sums are thread-count independent.
#include <cstddef>

#include "model/params.hpp"
#include "sim/energy.hpp"
#include "state/particles.hpp"

namespace mpdem {

struct StateScan {
  ParticleEnergy energy;        // J, kinetic, rotational, gravitational
  double electric = 0.0;        // J, potential in the uniform electric field, -sum q E.x
  std::size_t nonfinite = 0;    // particles with a non-finite x, v, w or T
  std::size_t outside = 0;      // particles outside the domain (0 when it is unbounded)
};

StateScan scan_state(const Particles& p, const FieldParams& fields, const DomainParams& domain);

// True when x lies in the closed box of a bounded domain (always true when unbounded).
inline bool inside_domain(const DomainParams& d, const Vec3& x) {
  return !d.bounded || (x.x >= d.min.x && x.x <= d.max.x && x.y >= d.min.y && x.y <= d.max.y && x.z >= d.min.z &&
                        x.z <= d.max.z);
}

}  // namespace mpdem
