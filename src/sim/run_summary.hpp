#pragma once
// What a run keeps for its end-of-run summary, step by step and through checkpoints: the energy
// balance (the one the energy_jump check uses) at the start and now, and the deepest contact
// seen. A run that drifts slowly passes every per-step check; only the whole-run figures show it.
#include <cstddef>
#include <cstdint>
#include <string>

#include "contact/particle_contacts.hpp"

namespace mpdem {

struct RunRecord {
  double start_balance = 0.0;   // J, energy balance after the first evaluation at t = 0
  double start_active = 0.0;    // J, kinetic + rotational + elastic energy then
  double peak_active = 0.0;     // J, largest kinetic + rotational + elastic energy after a step
  double balance = 0.0;         // J, energy balance after the last step
  double removed_energy = 0.0;  // J, kinetic + rotational + potential energy the removed particles took along
  OverlapReport deepest;        // the deepest contact seen (overlap / radius, ids)
  double deepest_time = 0.0;    // s, when it was seen
  bool started = false;         // start_balance and start_active are set

  // Every field in a fixed order, for the checkpoint's "run_record" section.
  template <class R, class F>
  static void for_each_field(R& r, F&& f) {
    f(r.start_balance);
    f(r.start_active);
    f(r.peak_active);
    f(r.balance);
    f(r.removed_energy);
    f(r.deepest.ratio);
    f(r.deepest.particle);
    f(r.deepest.other);
    f(r.deepest.element);
    f(r.deepest_time);
    f(r.started);
  }
};

// -, the balance's change over the run relative to the magnitude of the start balance (at least
// the start kinetic + rotational + elastic energy, so a balance that starts near zero is not
// divided by round-off; the largest such energy reached when both are zero).
double energy_drift(const RunRecord& r);

struct RunSummary {
  double time = 0.0;                // s, simulated time reached
  std::uint64_t steps = 0;          // steps of the whole run (a resumed run counts those before its checkpoint)
  std::uint64_t session_steps = 0;  // steps taken by this call of run() (after the checkpoint when resumed)
  std::uint64_t evaluations = 0;    // interaction evaluations
  std::size_t removed = 0;          // particles removed at the domain boundary
  RunRecord record;
  double drift_limit = 0.0;     // -, checks.energy_drift (0: no warning)
  std::string drift_unchecked;  // why the drift says nothing about the step (empty: it does)
  // false: [checks] energy_ledger = false, the contacts' dissipation is not in the balance, which
  // then measures nothing: the summary says so instead of a drift, and nothing warns.
  bool booked = true;
  // An open system (inlets or sinks): energy enters and leaves after t = 0, so the start balance
  // alone is no measure of it (0 J for a silo filled from empty).
  bool open = false;
  bool sinks = false;            // the scene has sinks
  std::size_t sunk = 0;          // particles removed by them
  double inserted_energy = 0.0;  // J, what the inlets' particles brought in
  double dissipated = 0.0;       // J, dissipated over the run (damping, friction, dissipative body forces)
};

// What the drift of a run is measured against: closed systems, as energy_drift(RunRecord); open
// ones, the largest of that, the energy dissipated and the largest kinetic + rotational +
// elastic energy reached (the energy the contacts handled; the inserted energy is not used: its
// gravitational part depends on where the coordinates' origin lies).
struct DriftReference {
  double energy = 0.0;  // J (0: nothing to measure against)
  const char* what = "the start balance";
};
DriftReference drift_reference(const RunSummary& s);
// -, the balance's change over the run relative to drift_reference(s).
double energy_drift(const RunSummary& s);

// "energy balance drift +0.012% of the start balance (...); largest overlap 1.2% of the radius
// between particles id 7 and id 8 at t = 0.0123 s"
std::string summary_line(const RunSummary& s);
// "125000 steps, 125002 interaction evaluations, 1556 particles removed at the domain boundary,
// 500 in sinks" (the sinks' count when the scene has sinks)
std::string counts_line(const RunSummary& s);
// The end-of-run warning when |drift| exceeds checks.energy_drift (checked runs only); empty otherwise.
std::string drift_warning(const RunSummary& s);

}  // namespace mpdem
