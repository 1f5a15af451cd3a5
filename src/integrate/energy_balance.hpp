#pragma once
// The energy balance (physics.md section 12): the particles' energies - kinetic 1/2 m v^2,
// rotational 1/2 j w^2, gravitational -m g.x - and the one function that adds the interaction
// statistics to them by their roles (interact/interaction_stats.hpp), used by the run's checks
// (Simulation) and by the log's total_energy (output/global_log). Sums are thread-count independent.
#include <cmath>

#include "model/params.hpp"
#include "interact/interaction_stats.hpp"
#include "state/particles.hpp"

namespace mpdem {

struct ParticleEnergy {
  double kinetic = 0.0;     // J
  double rotational = 0.0;  // J
  double potential = 0.0;   // J, gravitational, zero at the origin
};

ParticleEnergy particle_energy(const Particles& p, const Vec3& gravity);

// What the two users of the balance differ in.
// - The run's balance (energy_jump check, drift, RunRecord) books what the open system's inlets
//   brought in and what removed particles took away, so that it stays constant as particles come
//   and go; it leaves out the near field's potential, which the cutoff truncates (a pair
//   crossing it steps the total by U(cutoff)): near-field scenes are not checked.
// - The log's total_energy holds the particles present (it rises when an inlet inserts) and
//   includes the near field's potential (its own column).
struct BalanceScope {
  bool cut_potentials = false;  // include StatBalance::cut_potential rows (the near field)
  double inserted = 0.0;        // J, brought in by inlets, taken off
  double removed = 0.0;         // J, taken along by removed particles, added
};
inline constexpr BalanceScope kLogBalance{true, 0.0, 0.0};

// J, kinetic + rotational + (gravitational + electric potential) + the stored, dissipated (and,
// by scope, cut) statistics + removed - inserted - the supplied work. electric: J, -sum q E.x.
double energy_balance(const ParticleEnergy& e, double electric, const InteractionStats& s, const BalanceScope& scope);

// J, the energy the interactions dissipated so far (the rows of role dissipated, in table order).
double dissipated_energy(const InteractionStats& s);

// J, the energy in motion and in the contacts' springs: the scale of the energy checks. The stored
// elastic energy counts by its magnitude, since an adhesive contact's is negative at rest; with
// cohesion by the sum of the contacts' magnitudes (InteractionStats::elastic_magnitude), since
// necks at rest (negative) and loaded contacts (positive) can cancel in the sum.
inline double active_energy(const ParticleEnergy& e, double elastic, double magnitude = 0.0) {
  const double stored = std::abs(elastic);
  return e.kinetic + e.rotational + (magnitude > stored ? magnitude : stored);
}

}  // namespace mpdem
