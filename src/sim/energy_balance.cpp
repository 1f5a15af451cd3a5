#include "sim/energy_balance.hpp"

#include "sim/health_scan.hpp"

namespace mpdem {

ParticleEnergy particle_energy(const Particles& p, const Vec3& gravity) {
  // The same sums as the per-step health scan (one definition of the energies).
  FieldParams fields;
  fields.gravity = gravity;
  return scan_state(p, fields, DomainParams{}).energy;
}

}  // namespace mpdem
