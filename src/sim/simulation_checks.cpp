// The health checks after every step (simulation.hpp): energy jumps and overlaps beyond the
// scene's [checks] limits stop the run with the particles named.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "contact/particle_contacts.hpp"
#include "parallel/gather.hpp"
#include "core/run_error.hpp"
#include "integrate/energy_balance.hpp"
#include "sim/inlets.hpp"
#include "sim/simulation.hpp"

namespace mpdem {

double Simulation::energy_balance(const HealthScan& s) const {
  const double inserted = inlets_ ? inlets_->inserted_energy() : 0.0;  // J, what inlets brought in
  return mpdem::energy_balance(s.energy, s.electric, stats(), BalanceScope{false, inserted, record_.removed_energy});
}

void Simulation::record_state(const HealthScan& s) {
  // Without the ledger no balance is booked, and the step's scan summed no energies.
  if (!scene_.model.params.checks.energy_ledger) return;
  const double balance = energy_balance(s);
  const double active = active_energy(s.energy, stats().elastic_energy + stats().bond_energy,
                                      stats().elastic_magnitude);
  if (!record_.started) {
    record_.start_balance = balance;
    record_.start_active = active;
    record_.started = true;
  }
  record_.balance = balance;
  record_.peak_active = std::max(record_.peak_active, active);
}

void Simulation::record_overlap(const OverlapReport& r) {
  if (r.ratio > record_.deepest.ratio) {
    record_.deepest = r;
    record_.deepest_time = time_;
  }
}

void Simulation::check_energy(const HealthScan& s) {
  const Params& prm = scene_.model.params;
  // The near field's potential is not in the balance, so its scenes cannot be checked this way;
  // nor those without the contacts' ledger (a scene built in code may leave energy_jump set).
  if (!(prm.checks.energy_jump > 0.0) || prm.near_field.cutoff > 0.0 || !prm.checks.energy_ledger) return;
  const ParticleEnergy& e = s.energy;
  const double balance = energy_balance(s);
  const double active = active_energy(e, stats().elastic_energy + stats().bond_energy, stats().elastic_magnitude);
  if (energy_checked_) {
    const double rise = balance - last_balance_;
    // Round-off of the balance is relative to its largest term.
    const double noise = 1e-9 * (std::abs(e.potential) + active + std::abs(balance)) + 1e-15;
    // A moving barrier (or fixed particle) feeds energy in: what it put in during the step (its
    // drive power x dt) is part of the scale, so a particle at rest that a wall sets moving is not
    // a jump.
    const InteractionStats& st = stats();
    const double driven = (std::abs(st.drive_power) + std::abs(st.fixed_power) + std::abs(st.external_power)) *
                          dt_;  // J
    if (rise > prm.checks.energy_jump * (last_active_ + driven) + noise) {
      // Name the fastest particles: an exploding contact throws them apart.
      std::string ids;
      for (const Fastest& f : fastest(3))
        ids += fmt::format("{}{}{}", ids.empty() ? "" : ", ", f.id, rank_note(comm_, f.rank));
      throw RunError(fmt::format(
          "energy jump at step {} (t = {:.9g} s): the energy balance rose by {:.4g} J in one step, more than "
          "checks.energy_jump = {} x the kinetic + elastic energy {:.4g} J; fastest particles: ids {}. The step "
          "is too large for the contacts; reduce time.dt (see `mpdem check` for a recommended step).",
          steps_, time_, rise, prm.checks.energy_jump, last_active_, ids));
    }
  }
  last_balance_ = balance;
  last_active_ = active;
  energy_checked_ = true;
}

std::vector<Simulation::Fastest> Simulation::fastest(std::size_t k) const {
  const Particles& p = scene_.particles;
  std::vector<Fastest> mine(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) mine[i] = {norm2(p.v[i]), p.id[i], comm_ ? comm_->rank() : -1};
  const auto faster = [](const Fastest& a, const Fastest& b) { return a.v2 > b.v2 || (a.v2 == b.v2 && a.id < b.id); };
  const auto keep_first = [&](std::vector<Fastest>& v) {
    const std::size_t n = std::min(k, v.size());
    std::partial_sort(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(n), v.end(), faster);
    v.resize(n);
  };
  keep_first(mine);
  if (!comm_) return mine;
  std::vector<Fastest> all = all_gather_values<Fastest>(*comm_, mine);
  keep_first(all);
  return all;
}

void Simulation::check_overlap(const OverlapReport& r) {
  record_overlap(r);
  const double limit = scene_.model.params.checks.max_overlap;
  if (!(limit > 0.0)) return;
  if (!(r.ratio > limit)) return;
  const std::string between = r.element >= 0 ? fmt::format("particle id {}{} and barrier element id {}", r.particle,
                                                           rank_note(comm_, r.rank), r.element)
                                             : fmt::format("particles id {} and id {}{}", r.particle, r.other,
                                                           rank_note(comm_, r.rank));
  throw RunError(fmt::format(
      "overlap of {:.3g}% of the radius between {} at step {} (t = {:.9g} s), more than checks.max_overlap = {:.3g}%. "
      "The contact is not resolved: reduce time.dt (see `mpdem check` for a recommended step) or raise young.",
      100.0 * r.ratio, between, steps_, time_, 100.0 * limit));
}

}  // namespace mpdem
