#pragma once
// The global log's columns and one row of values (docs/output.md, log.csv): written by the
// OutputManager and read by the Python module's Simulation.log(), so both name and compute every
// quantity the same way.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "integrate/step_report.hpp"
#include "model/scene.hpp"
#include "integrate/energy_balance.hpp"
#include "interact/interactions.hpp"

namespace mpdem {

// One row of the global log.
struct GlobalLogRow {
  std::uint64_t step = 0;
  double time = 0.0, dt = 0.0;
  const StepReport* report = nullptr;
  std::uint64_t evaluations_total = 0;
  std::uint64_t redone_steps = 0;
  std::size_t removed_total = 0;
  // The inlets' and sinks' columns (Inlets::log_columns, Sinks::log_columns), in that order.
  std::vector<double> open_system;
  // The bonds broken as of the previous log row (with [bonds]: bonds_broken_interval counts from it).
  std::uint64_t bonds_broken_before = 0;
};

// The sums over the particles in a global log row; on several ranks each rank's, summed over them.
struct ParticleTotals {
  ParticleEnergy energy;  // J, kinetic, rotational, gravitational
  double electric = 0.0;  // J, potential in the uniform electric field
  double count = 0.0;     // particles
  double thermal = 0.0;   // J, sum m c T (with [analysis] thermal; else 0)
  double bodies = 0.0;    // clump bodies
  double members = 0.0;   // member spheres of the bodies (counted in `count` too)
};
ParticleTotals particle_totals(const Model& model, const Particles& p);

// Which columns a scene's log has: the optional ones only for the physics it turns on, so plain
// mechanical logs keep their shape.
class GlobalLogLayout {
 public:
  // open_system_columns: the inlets' and sinks' column names (GlobalLogRow::open_system's), last.
  GlobalLogLayout(const Model& model, const Barriers& barriers, const std::vector<std::string>& open_system_columns);
  const std::vector<std::string>& columns() const { return columns_; }
  // The row's values, in columns() order.
  std::vector<double> values(const GlobalLogRow& row, const ParticleTotals& totals,
                             const InteractionStats& stats) const;

 private:
  std::vector<std::string> columns_;
  // Which statistics have a column (interact/interaction_stats.hpp: the optional ones only for the
  // physics the scene turns on), by row of kStats.
  std::array<bool, kStatCount> logged_{};
  bool thermal_ = false;  // log the thermal energy (after the heat exchanged with the outside)
  bool bodies_ = false;   // log the clumps' bodies and members (a scene with clump templates)
  bool bonds_ = false;    // log the bonds broken in the interval (a scene with [bonds])
  bool ledger_ = true;    // the contacts' energy ledger: total_energy is logged
};

}  // namespace mpdem
