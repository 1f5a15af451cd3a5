#include "integrate/energy_balance.hpp"

#include "integrate/health_scan.hpp"

namespace mpdem {

ParticleEnergy particle_energy(const Particles& p, const Vec3& gravity) {
  // The same sums as the per-step health scan (one definition of the energies).
  FieldParams fields;
  fields.gravity = gravity;
  return scan_state(p, fields, DomainParams{}).energy;
}

double energy_balance(const ParticleEnergy& e, double electric, const InteractionStats& s, const BalanceScope& scope) {
  // A fixed order of the terms (the stored and dissipated ones, then the supplied work), so that
  // both users get the same bits for the same state.
  double b = -scope.inserted;
  b += e.kinetic;
  b += e.rotational;
  b += e.potential + electric;
  for_each_stat(s, [&](const StatInfo& info, const auto& v) {
    if (info.balance == StatBalance::stored || info.balance == StatBalance::dissipated ||
        (scope.cut_potentials && info.balance == StatBalance::cut_potential))
      b += static_cast<double>(v);
  });
  b += scope.removed;
  for_each_stat(s, [&](const StatInfo& info, const auto& v) {
    if (info.balance == StatBalance::supplied) b -= static_cast<double>(v);
  });
  return b;
}

double dissipated_energy(const InteractionStats& s) {
  double d = 0.0;
  for_each_stat(s, [&](const StatInfo& info, const auto& v) {
    if (info.balance == StatBalance::dissipated) d += static_cast<double>(v);
  });
  return d;
}

}  // namespace mpdem
