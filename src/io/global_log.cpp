#include "io/global_log.hpp"

#include <algorithm>

#include "field/near_field_forces.hpp"
#include "sim/inlets.hpp"
#include "sim/sinks.hpp"
#include "sim/health_scan.hpp"
#include "thermal/heat_transfer.hpp"

namespace mpdem {

ParticleTotals particle_totals(const Model& model, const Particles& p) {
  const HealthScan scan = scan_state(p, model.params.fields, DomainParams{});
  return {scan.energy, scan.electric, static_cast<double>(p.size()),
          model.params.analysis.thermal ? thermal_energy(model, p) : 0.0};
}

GlobalLogLayout::GlobalLogLayout(const Model& model, const Barriers& barriers)
    : columns_{"step",         "time",      "dt",      "iterations",         "evaluations",         "evaluations_total",
               "redone_steps", "particles", "removed", "contacts_pp",        "contacts_pb",         "kinetic",
               "rotational",   "potential", "elastic", "damping_dissipated", "friction_dissipated", "total_energy"} {
  near_field_ = near_field_enabled(model.params.near_field);
  thermal_ = model.params.analysis.thermal;
  if (near_field_) columns_.insert(columns_.end() - 1, "near_field");  // part of total_energy
  driven_ = std::any_of(barriers.motion.begin(), barriers.motion.end(),
                        [](const MotionLaw& m) { return !m.is_static(); });
  if (driven_) columns_.insert(columns_.end() - 1, "barrier_work");  // taken off total_energy
  if (thermal_)
    for (const char* c : {"heat_to_barriers", "heat_convected", "heat_radiated", "thermal_energy"})
      columns_.push_back(c);
  for (auto* open : {&Inlets::log_columns, &Sinks::log_columns})
    for (std::string& c : open(model.params)) columns_.push_back(std::move(c));
}

std::vector<double> GlobalLogLayout::values(const GlobalLogRow& r, const ParticleTotals& t,
                                            const InteractionStats& s) const {
  const ParticleEnergy& e = t.energy;
  const double potential = e.potential + t.electric;  // J, gravitational + electric
  const double nf = near_field_ ? s.near_field_energy : 0.0;
  const double total = e.kinetic + e.rotational + potential + s.elastic_energy + s.damping_dissipated +
                       s.friction_dissipated + nf - s.barrier_work - s.fixed_work - s.external_work;
  std::vector<double> row{static_cast<double>(r.step),
                          r.time,
                          r.dt,
                          static_cast<double>(r.report ? r.report->iterations : 0),
                          static_cast<double>(r.report ? r.report->evaluations : 0),
                          static_cast<double>(r.evaluations_total),
                          static_cast<double>(r.redone_steps),
                          t.count,
                          static_cast<double>(r.removed_total),
                          static_cast<double>(s.contacts_pp),
                          static_cast<double>(s.contacts_pb),
                          e.kinetic,
                          e.rotational,
                          potential,
                          s.elastic_energy,
                          s.damping_dissipated,
                          s.friction_dissipated};
  if (near_field_) row.push_back(nf);
  if (driven_) row.push_back(s.barrier_work);
  row.push_back(total);
  if (thermal_) {
    row.push_back(s.heat_to_barriers);
    row.push_back(s.heat_convected);
    row.push_back(s.heat_radiated);
    row.push_back(t.thermal);
  }
  row.insert(row.end(), r.open_system.begin(), r.open_system.end());
  return row;
}

}  // namespace mpdem
