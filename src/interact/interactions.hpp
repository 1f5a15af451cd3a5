#pragma once
// Interactions: everything that produces forces, torques and heat flows from a state, in the
// order of a step: neighbour search, field forces, near-field forces, particle-particle
// contacts, particle-barrier contacts, heat transfer (when [analysis] thermal is on). One
// evaluation fills Particles::force/torque/heat and the barriers' loads for the positions,
// velocities and temperatures currently stored in the arrays. The integrators call
// it at coarse grain; the laws themselves are small functions in src/physics/.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <exception>
#include <memory>
#include <utility>
#include <span>
#include <vector>

#include "contact/cohesion_reach.hpp"
#include "contact/contact_table.hpp"
#include "contact/eval_request.hpp"
#include "core/heap_policy.hpp"
#include "interact/step_policy.hpp"
#include "core/binary_stream.hpp"
#include "io/checkpoint_format.hpp"
#include "model/scene.hpp"
#include "parallel/attached_records.hpp"
#include "interact/external_loads.hpp"
#include "interact/interaction_stats.hpp"

namespace mpdem {

// Wall time spent per part of the evaluations (s, cumulative; not checkpointed), for the
// benchmark's breakdown of where a step goes.
struct PhaseTimes {
  double search = 0.0;    // rebuild checks and rebuilds (prepare_step's, with reordering, too)
  double fields = 0.0;    // accumulators reset, field forces
  double pairs = 0.0;     // particle-particle contacts
  double barriers = 0.0;  // particle-barrier contacts and element loads
  double other = 0.0;     // near field, heat
  double exchange = 0.0;  // ghosts refreshed and folded, barrier loads summed over the ranks (with waits)
};

struct OverlapReport;
class BrickGrid;
class Communicator;
class NeighborSearch;
struct PairStats;
class ParticleContacts;
class BarrierContacts;
class NearFieldForces;
class HeatTransfer;
class Bonds;
struct HeatFlows;

class Interactions {
 public:
  // Builds the neighbour search for the scene's particles and barriers; `policy` is what the
  // integrator that will call evaluate() needs (its policy() function).
  Interactions(const Model& model, const Particles& p, const Barriers& b, const StepPolicy& policy);
  ~Interactions();

  // The stage before every step (of length dt, s): rebuilds the lists when they might not last
  // through the step, and then reorders the particles spatially (ids are kept; contact history
  // and the force accumulators follow the particles). The only place that reorders. dt = 0:
  // rebuilds only when the lists are already stale.
  void prepare_step(Particles& p, const Barriers& b, double dt = 0.0);
  // The next step's list check, for an integrator whose last pass computes the next drift
  // (StepPolicy::drift_known): it counts the particles drift_beyond (interact/verlet_drift.hpp)
  // x_build by more than sqrt(lim2), and hands the count to record_next_drift, which spares
  // prepare_step a pass over the particles. x_build is null when no such check is possible.
  struct DriftCheck {
    const Vec3* x_build = nullptr;  // m, positions at the last build [N]
    double lim2 = 0.0;              // m^2, squared displacement allowed (skin/2 less the barriers' reach)
    double limit = 0.0;             // m
    double dt = 0.0;                // s, the next step's length the check assumes
  };
  DriftCheck next_drift_check(const Particles& p, const Barriers& b, double dt) const;
  void record_next_drift(const DriftCheck& c, const Particles& p, std::size_t beyond);
  // The list check of an evaluation, for an integrator whose pass writes the positions it will
  // see (the trapezoidal rule's predictor and updates): that pass measures the largest squared
  // displacement (m^2) of the owned particles from build_positions() [N] (null: stale lists, no
  // measurement) and hands it over just before the evaluation, which then needs no pass of its
  // own over the particles. Consumed by that evaluation; -1: not measured.
  const Vec3* build_positions(const Particles& p, const Barriers& b) const;
  void set_measured_displacement(double max2) { measured_displacement2_ = max2; }
  // Fills force, torque, heat of every particle (and the barriers' loads) for the current state.
  // Never reorders. Should the particles have moved beyond what prepare_step foresaw, it rebuilds
  // the lists in place first (counted by mid_step_rebuilds()).
  void evaluate(Particles& p, Barriers& b, const EvalRequest& req);
  // The same evaluation with every pass in the caller's parallel region (velocity Verlet's step,
  // integrate/verlet.cpp): every thread of the team calls it, and it returns to all of them
  // after a barrier; the serial parts run on one thread (omp single). Only when team_ready(p).
  // Should a serial part throw, every thread returns at once and team_error() holds what it threw
  // (to rethrow after the region); it stays set until take_team_error(). next (shared, or null):
  // set to next_drift_check(p, b, req.dt) before that barrier.
  void evaluate_in_team(Particles& p, Barriers& b, const EvalRequest& req, DriftCheck* next);
  // Whether evaluate_in_team can run this scene: one rank, and none of the parts whose passes
  // open their own parallel regions or need a collective (near field, heat, bonds, clumps,
  // external loads, a body force besides gravity).
  bool team_ready(const Particles& p) const;
  // Off: team_ready() is false, so the step keeps a parallel region per pass (for tests that
  // compare the two, and for measurements). On by default.
  void set_one_region(bool on) { one_region_ = on; }
  bool team_error() const { return team_error_ != nullptr; }
  std::exception_ptr take_team_error() { return std::exchange(team_error_, nullptr); }
  // Removes the particles whose keep[i] is 0, keeping everyone else's contact history.
  void remove_particles(Particles& p, const Barriers& b, const std::vector<char>& keep);
  // Before remove_particles: whether removing them changes the others' rates or the step's
  // totals, so that the rates must be evaluated again. Not when none of them touches a particle
  // or barrier element and only contacts and field forces act (interact/interactions_open_system.cpp).
  // Collective.
  bool removal_acts_on_others(const Particles& p, const std::vector<char>& keep) const;
  // Appends the particles `fresh` (an inlet's, sim/inlets.hpp) after the others, keeping every
  // existing contact's history; the new ones start without any.
  void add_particles(Particles& p, const Barriers& b, Particles fresh);
  // Rebuilds now (optionally reordering) - for tests of rebuild invariance.
  void force_rebuild(Particles& p, const Barriers& b, bool reorder);

  // A run over the ranks of `comm` (interactions_decomposed.cpp, docs/parallel.md): p holds this
  // rank's particles (those in its brick of `grid`); ghosts come from the neighbouring bricks,
  // rebuilds are collective, particles migrate at the reordering rebuilds with their history,
  // and every decision (rebuild, stale lists) is taken over all ranks. `body_margin` (m): the
  // halo's growth for clumps (NeighborSearch::decompose).
  void decompose(const Communicator& comm, const BrickGrid& grid, double body_margin = 0.0);
  bool decomposed() const { return comm_ != nullptr; }
  // Records of another part of the run (the trapezoidal rule's rate history) that travel with
  // their particles (anchored by particle ids) or their clumps' bodies (by body ids) when these
  // change rank: taken before a migration, given back after it.
  struct TravellingRecords {
    std::function<AttachedRecords()> take;
    std::function<void(const AttachedRecords&)> give;
  };
  void set_travelling(TravellingRecords particles, TravellingRecords bodies = {}) {
    travelling_ = std::move(particles);
    body_travelling_ = std::move(bodies);
  }
  // Statistics summed over the ranks (the barriers' drive power and work are already global:
  // their loads are summed over the ranks at every evaluation that reads them). Collective.
  InteractionStats global_stats() const;
  // Several ranks: from prepare_step to the step's totals (Simulation::reduce_step), an
  // evaluation whose barriers are all at rest leaves the barrier loads this rank's own (such
  // barriers do no work, so nothing in the step reads the sum): one collective less a step.
  // Then barrier_loads() are this rank's (7 per element: force, moment, pressure), to be summed
  // with the step's totals; end_step_loads puts the sum back (if pending) and ends the deferral.
  bool barrier_loads_pending() const { return loads_pending_; }
  std::vector<double> barrier_loads(const Barriers& b) const;
  void end_step_loads(Barriers& b, std::span<const double> summed);

  const InteractionStats& stats() const { return stats_; }
  // The contacts keep a cohesion state (a law with hysteresis or liquid bridges): bridges, breaks.
  bool cohesive() const { return gaps_.cohesive; }
  // Forces and torques added to particles by a caller, between steps (interact/external_loads.hpp).
  ExternalLoads& external_loads() { return external_; }
  const PhaseTimes& times() const { return times_; }
  // Several ranks: max / mean of the ranks' cost at the last load-balance measurement
  // ([parallel] balance_every; 0 before the first, and on one rank), whether the cut planes moved
  // then, the times they moved, and the measurements taken.
  double imbalance() const { return imbalance_; }
  bool moved_at_last_measurement() const { return moved_; }
  std::uint64_t balances() const { return balances_; }
  std::uint64_t balance_measurements() const { return measurements_; }
  // Rebuilds evaluate() had to do (prepare_step's criterion should make them rare; not
  // checkpointed, so a resumed run counts from 0).
  std::uint64_t mid_step_rebuilds() const { return mid_step_rebuilds_; }
  // Checkpoints: statistics, neighbour lists and contact history.
  // Checkpoint sections "interactions", "neighbor", "particle_contacts", "barrier_contacts".
  void save(CheckpointWriter& w, const Particles& p) const;
  // Several ranks (collective): the same sections for every particle, written by rank 0 alone;
  // `all` holds every rank's particles in id order there (Simulation::gathered), and the lists'
  // build positions and the contact history are keyed by ids, so any rank count resumes them.
  void save_gathered(CheckpointWriter& w, const Particles& p, const Particles& all) const;
  // On several ranks p holds every particle of the checkpoint; those of this rank's brick stay.
  void restore(CheckpointReader& r, Particles& p, const Barriers& b);
  double skin() const;
  const NeighborSearch& search() const { return *search_; }
  const ParticleContacts& particle_contacts() const { return *particle_contacts_; }
  ParticleContacts& particle_contacts() { return *particle_contacts_; }
  const BarrierContacts& barrier_contacts() const { return *barrier_contacts_; }
  // The parallel bonds ([bonds]; null without): made at construction from the particles given.
  const Bonds* bonds() const { return bonds_.get(); }
  Bonds* bonds() { return bonds_.get(); }
  // Several ranks, after the particles were split (Simulation::decompose): keeps the bonds of
  // this rank's particles (interact/interactions_bonds.cpp).
  void keep_owned_bonds(const Particles& p);
  // The deepest particle-particle or particle-barrier contact of the last evaluation.
  OverlapReport max_overlap(const Particles& p, const Barriers& b) const;
  // Evaluations in which the convection fit's air speed clamp (20 m/s) engaged.
  std::uint64_t convection_clamps() const;

 private:
  // force = body forces, torque = heat = 0; returns the power the body forces dissipate (W).
  double start_accumulators(Particles& p) const;
  // Its pass when gravity is the only body force (BodyForces::only_first), as an orphaned
  // work-sharing loop: every thread of a team calls it, or one thread outside a region.
  void start_first_forces(Particles& p) const;
  // evaluate()'s serial parts: the lists' safety net and the ghosts' state before the passes,
  // and the statistics from the passes' totals (field_power: W, the body forces' dissipation).
  void prepare_evaluation(Particles& p, Barriers& b, const EvalRequest& req);
  void book_evaluation(const Particles& p, const Barriers& b, const EvalRequest& req, const PairStats& pp,
                       const PairStats& pb, double field_power);
  void commit_heat(const HeatFlows& h, const EvalRequest& req);
  // The bonds' forces and their statistics (interact/interactions_bonds.cpp).
  void evaluate_bonds(Particles& p, const EvalRequest& req);
  void rebuild(Particles& p, const Barriers& b, bool reorder);
  bool rebuild_due(const Particles& p, const Barriers& b, double dt) const;
  // Lists never built, or particles or barrier elements added or removed since.
  bool stale(const Particles& p, const Barriers& b) const;
  // m, an allowance for the barriers' displacement since the build, to the end of a step of dt.
  double barrier_reach(const Barriers& b, double dt) const;
  // Whether velocity Verlet's drift dx = dt (v + dt/2 F/m) leaves every particle within limit (m)
  // of its position at the last build (since_build) or of its present position.
  bool drift_within(const Particles& p, double dt, double limit, bool since_build) const;
  // Several ranks: v on every rank when some rank has it (any) or all have it (all); else v.
  bool any_rank(bool v) const;
  bool all_ranks(bool v) const { return !any_rank(!v); }
  // The decomposed rebuild: history keyed by ids, migration at reordering rebuilds.
  void rebuild_decomposed(Particles& p, const Barriers& b, bool reorder);
  // Element loads summed over the ranks, unless they may wait (barrier_loads_pending).
  void reduce_barrier_loads(Barriers& b);
  // Every [parallel] balance_every steps: the ranks' cost measured, and when its imbalance
  // exceeds balance_threshold the cut planes moved and the particles migrated (a rebuild).
  void balance_if_due(Particles& p, const Barriers& b);

  const Model& model_;
  StepPolicy policy_;
  ContactTable table_;  // the contact laws by pair of materials, rebuilt from model_ at every evaluation
  CohesionGaps gaps_;   // how far contacts reach beyond touching (contact/cohesion_reach.hpp), from the start
  InteractionStats stats_;
  ExternalLoads external_;
  PhaseTimes times_;
  std::exception_ptr team_error_;  // what a serial part of evaluate_in_team threw
  bool team_barriers_ = false;     // evaluate_in_team: the barrier contacts have a pass this evaluation
  bool one_region_ = true;         // see set_one_region
  std::uint64_t mid_step_rebuilds_ = 0;
  RebuildHeapPolicy heap_policy_;  // a rare rebuild's large arrays in mappings of their own
  // m, bound on the particles' displacement since the build at the next evaluation, set by
  // prepare_step when the step's drift is known (StepPolicy::drift_known); -1: unknown.
  double predicted_displacement_ = -1.0;
  double measured_displacement2_ = -1.0;  // m^2, set_measured_displacement's; -1: none
  // The integrator's check of the coming step (record_next_drift), valid until the state, the
  // forces or the lists change (an evaluation, a rebuild, a removal, a restore).
  struct NextDrift {
    bool valid = false;
    bool within = false;  // every particle's drift within limit of its build position
    double limit = 0.0;   // m
    double dt = 0.0;      // s
    std::size_t n = 0;    // particles
  } next_drift_;
  const Communicator* comm_ = nullptr;  // several ranks (decompose()); null in a one-rank run
  TravellingRecords travelling_;        // several ranks: carried along by migrations
  TravellingRecords body_travelling_;   // the same, anchored by body ids
  bool defer_loads_ = false;            // within a step: loads of barriers at rest may wait
  bool loads_pending_ = false;          // the barrier loads are this rank's alone, to be summed
  std::uint64_t steps_since_balance_ = 0;
  double busy_at_balance_ = 0.0;  // s, evaluation time (times_ without search, exchange) at the last measurement
  double imbalance_ = 0.0;        // -, see imbalance()
  bool moved_ = false;            // see moved_at_last_measurement()
  std::uint64_t balances_ = 0;
  std::uint64_t measurements_ = 0;
  std::unique_ptr<NeighborSearch> search_;
  std::unique_ptr<ParticleContacts> particle_contacts_;
  std::unique_ptr<BarrierContacts> barrier_contacts_;
  std::unique_ptr<NearFieldForces> near_;  // null when the near field is off
  std::unique_ptr<HeatTransfer> heat_;     // null when [analysis] thermal is off
  std::unique_ptr<Bonds> bonds_;           // null without [bonds]
  double bond_margin_ = 0.0;               // m, the halo's growth for the bonds (decompose)
  // Outward heat flows (W) of the last committed evaluation, the start values of the next step.
  double out_barriers_ = 0.0, out_convected_ = 0.0, out_radiated_ = 0.0;
};

// Verlet skin used for a scene: [neighbor] skin, or 0.1 x the smallest particle diameter.
double default_skin(const Model& model, const Particles& p);

}  // namespace mpdem
