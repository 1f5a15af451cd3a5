// Interactions' parallel bonds (contact/bonds.hpp): their forces within an evaluation, their
// statistics, and their share of a decomposed run.
#include "contact/bonds.hpp"
#include "core/scoped_timer.hpp"
#include "interact/interactions.hpp"

namespace mpdem {

void Interactions::evaluate_bonds(Particles& p, const EvalRequest& req) {
  ScopedTimer timer(times_.other);
  const BondStats s = bonds_->evaluate(p, req);
  stats_.bonds_intact = s.intact;
  stats_.bond_energy = s.energy;
  if (!req.commit) return;
  stats_.bonds_broken += s.broken;
  stats_.bond_break_dissipated += s.broken_energy;
  // The dashpots' power by the trapezoid over the step, as the contacts' (Interactions::evaluate).
  stats_.bond_damping_dissipated += 0.5 * req.dt * (stats_.bond_damping_power + s.damping_power);
  stats_.bond_damping_power = s.damping_power;
}

void Interactions::keep_owned_bonds(const Particles& p) {
  if (bonds_) bonds_->keep_owned(p);
}

}  // namespace mpdem
