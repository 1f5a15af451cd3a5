#include "output/global_log.hpp"

#include "contact/cohesion_reach.hpp"

#include <algorithm>

#include "field/near_field_forces.hpp"
#include "interact/body_forces.hpp"
#include "integrate/health_scan.hpp"
#include "thermal/heat_transfer.hpp"

namespace mpdem {

ParticleTotals particle_totals(const Model& model, const Particles& p) {
  const HealthScan scan = scan_state(p, model.params.fields, DomainParams{});
  ParticleTotals t{scan.energy, scan.electric, static_cast<double>(p.size()),
                   model.params.analysis.thermal ? thermal_energy(model, p) : 0.0};
  if (p.has_bodies()) {
    t.bodies = static_cast<double>(p.bodies.size());
    t.members = static_cast<double>(std::count_if(p.body.begin(),
                                                  p.body.begin() + static_cast<std::ptrdiff_t>(p.size()),
                                                  [](std::int64_t b) { return b != kNoBody; }));
  }
  return t;
}

GlobalLogLayout::GlobalLogLayout(const Model& model, const Barriers& barriers,
                                 const std::vector<std::string>& open_system_columns) {
  thermal_ = model.params.analysis.thermal;
  bodies_ = !model.clumps.empty();
  bonds_ = model.params.bonds.enabled();
  ledger_ = model.params.checks.energy_ledger;
  const bool driven = std::any_of(barriers.motion.begin(), barriers.motion.end(),
                                  [](const MotionLaw& m) { return !m.is_static(); });
  const bool cohesion = has_cohesion(model);
  for (std::size_t k = 0; k < kStatCount; ++k) {
    switch (kStats[k].logged) {
      case StatLogged::never: logged_[k] = false; break;
      case StatLogged::always: logged_[k] = true; break;
      case StatLogged::ledger: logged_[k] = ledger_; break;
      case StatLogged::near_field: logged_[k] = near_field_enabled(model.params.near_field); break;
      case StatLogged::driven_barriers: logged_[k] = driven; break;
      case StatLogged::thermal: logged_[k] = thermal_; break;
      case StatLogged::dissipative_field: logged_[k] = dissipative_fields(model.params.fields); break;
      case StatLogged::cohesion: logged_[k] = cohesion; break;
      case StatLogged::bonds: logged_[k] = model.params.bonds.enabled(); break;
    }
  }
  columns_ = {"step",         "time",      "dt",     "iterations", "evaluations", "evaluations_total",
              "redone_steps", "particles", "removed"};
  if (bodies_) columns_.insert(columns_.end() - 1, {"bodies", "members"});  // after particles
  const auto stat_columns = [&](StatSlot slot) {
    for (std::size_t k = 0; k < kStatCount; ++k)
      if (logged_[k] && kStats[k].slot == slot) columns_.push_back(kStats[k].column);
  };
  stat_columns(StatSlot::counts);
  if (bonds_) columns_.push_back("bonds_broken_interval");  // after bonds_broken, the last count
  for (const char* c : {"kinetic", "rotational", "potential"}) columns_.push_back(c);
  stat_columns(StatSlot::energies);
  stat_columns(StatSlot::supplied);                 // taken off total_energy
  if (ledger_) columns_.push_back("total_energy");  // without the ledger, the sum lacks the dissipation
  stat_columns(StatSlot::heat);
  if (thermal_) columns_.push_back("thermal_energy");
  columns_.insert(columns_.end(), open_system_columns.begin(), open_system_columns.end());
}

std::vector<double> GlobalLogLayout::values(const GlobalLogRow& r, const ParticleTotals& t,
                                            const InteractionStats& s) const {
  const ParticleEnergy& e = t.energy;
  std::vector<double> row{static_cast<double>(r.step),
                          r.time,
                          r.dt,
                          static_cast<double>(r.report ? r.report->iterations : 0),
                          static_cast<double>(r.report ? r.report->evaluations : 0),
                          static_cast<double>(r.evaluations_total),
                          static_cast<double>(r.redone_steps),
                          t.count,
                          static_cast<double>(r.removed_total)};
  if (bodies_) row.insert(row.end() - 1, {t.bodies, t.members});
  const auto stat_values = [&](StatSlot slot) {
    std::size_t k = 0;
    for_each_stat(s, [&](const StatInfo& info, const auto& v) {
      if (logged_[k++] && info.slot == slot) row.push_back(static_cast<double>(v));
    });
  };
  stat_values(StatSlot::counts);
  if (bonds_) row.push_back(static_cast<double>(s.bonds_broken - r.bonds_broken_before));
  row.push_back(e.kinetic);
  row.push_back(e.rotational);
  row.push_back(e.potential + t.electric);  // J, gravitational + electric
  stat_values(StatSlot::energies);
  stat_values(StatSlot::supplied);
  if (ledger_) row.push_back(energy_balance(e, t.electric, s, kLogBalance));
  stat_values(StatSlot::heat);
  if (thermal_) row.push_back(t.thermal);
  row.insert(row.end(), r.open_system.begin(), r.open_system.end());
  return row;
}

}  // namespace mpdem
