#pragma once
// Simulation: the top-down driver of a run. One step reads
//   prepare_step (neighbour rebuild, reordering) -> integrator (its evaluations of the
//   interactions) -> checks -> output
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "integrate/step_report.hpp"
#include "integrate/trapezoidal.hpp"
#include "integrate/verlet.hpp"
#include "io/scene_fingerprint.hpp"
#include "model/scene.hpp"
#include "integrate/energy_balance.hpp"
#include "sim/run_summary.hpp"
#include "integrate/health_scan.hpp"
#include "sim/step_collective.hpp"
#include "parallel/communicator.hpp"
#include "interact/interactions.hpp"
#include "contact/bonds.hpp"

namespace mpdem {

class OutputManager;
class AnalysisOutputs;
struct ParticleSnapshotsDue;
class Progress;
class Inlets;
class Sinks;
struct GlobalLogRow;
struct ParticleTotals;

struct RunOptions {
  std::filesystem::path output_dir;  // empty: the scene's [output] dir, relative to the scene
  bool progress = true;              // progress line on stderr
  bool write_output = true;          // false: no files at all (tests)
  // The ranks that share the run (docs/parallel.md); null: Communicator::world(), all of them.
  const Communicator* comm = nullptr;
  // SIGINT / SIGTERM stop the run cleanly after the current step (a checkpoint, then Interrupted).
  // false: the caller handles signals (the Python module asks Python's handlers between steps).
  bool stop_on_signal = true;
  // Keep the bonds' breaks for take_bond_breaks (the Python module); else only bonds_broken.csv has them.
  bool keep_bond_breaks = false;
};

// Output folder of a run: options.output_dir, else the scene's [output] dir relative to the scene.
std::filesystem::path output_dir_for(const Scene& scene, const RunOptions& options);

// s, how far short of `end` the time of a run with step `dt` still counts as there (a few units
// in the last place of `end`, never less than a billionth of the step): Simulation::reached.
double end_round_off(double end, double dt);
// The steps of `dt` that a fixed-step run of `duration` takes (the last one whole when it ends
// within end_round_off of the end, cut otherwise).
std::uint64_t fixed_step_count(double duration, double dt);

class Simulation {
 public:
  // Owns the scene from here on: its model and state are read and changed through model(),
  // particles(), barriers(). An rvalue, so that no caller keeps reading a stale copy.
  Simulation(Scene&& scene, RunOptions options);
  ~Simulation();
  Simulation(const Simulation&) = delete;  // the parts hold references into scene_
  Simulation& operator=(const Simulation&) = delete;

  RunSummary run();  // runs to [time] duration; the summary says how trustworthy the run was
  // Whether the time has reached `end` (s): only round-off of the time separates them. step(end)
  // takes a step whole when it ends within that of `end`, and cuts it to land on `end` otherwise.
  bool reached(double end) const;

  // run() in parts, for callers that act between steps (the Python module): start() opens the
  // outputs and writes the first snapshots (once; step() and finish() call it); step(end) takes one
  // accepted step, ending at `end` (s) at the latest, with its outputs, checkpoint and stop
  // signal as run() does; finish() writes the final snapshots and returns the summary.
  void start();
  void step(double end);
  RunSummary finish();
  void flush_outputs();  // every output file complete as of the last step
  std::filesystem::path output_dir() const { return output_dir_for(scene_, options_); }
  // After a caller changed the state between steps (positions, velocities, temperatures): the
  // neighbour lists rebuilt and the rates evaluated at the new state, as at the start of a run;
  // the energy checks measure from the new state.
  void state_changed();
  // Between steps, on one rank (the Python module; sim/simulation_edits.cpp). add_particles
  // appends `fresh`, whose ids must be new (InputError naming the first taken one); inlets then
  // number their particles after them. remove_particles removes the particles `ids` (InputError
  // for an unknown id), writes them to removed.csv (not counted as domain exits) and keeps the
  // energy they take along in the balance. Both keep the other particles' contact history and
  // re-evaluate the rates.
  void add_particles(Particles fresh);
  void remove_particles(const std::vector<std::int64_t>& ids);
  std::int64_t next_free_id() const;  // one more than the largest id used by a particle or inlet
  // Parallel bonds between steps, on one rank (sim/simulation_bonds.cpp). add_bond bonds the
  // particles of ids a != b at their present positions (InputError: no [bonds], an unknown id,
  // a == b, a pair bonded already). take_bond_breaks: the breaks since the last call, in the
  // order of bonds_broken.csv (with RunOptions::keep_bond_breaks; else none).
  void add_bond(std::int64_t a, std::int64_t b);
  std::vector<BondBreak> take_bond_breaks();
  // The global log's quantities now, by column name as in log.csv (collective on several ranks).
  std::vector<std::pair<std::string, double>> log_values() const;

  // Finer control, for tests and tools.
  void initialize();              // first evaluation of the rates at t = 0
  StepReport advance(double dt);  // one accepted step of length dt (throws RunError on failure)
  // One accepted adaptive step (physics.md section 10): tries the current step, shrinks and
  // redoes it until the iteration converges within desired_iterations, then sets the next dt.
  // `limit` caps the step (to land exactly on the end time).
  StepReport advance_adaptive(double limit);
  double current_dt() const { return dt_; }
  // Checkpoints (sim/simulation_checkpoint.cpp): write the full state; resume before run() (throws InputError
  // for a file that is not a checkpoint of this scene).
  void write_checkpoint(const std::filesystem::path& file);
  void resume_from(const std::filesystem::path& file);
  std::uint64_t redone_steps() const { return redone_; }
  std::uint64_t evaluations() const { return evaluations_; }
  double time() const { return time_; }
  const RunRecord& record() const { return record_; }
  std::uint64_t steps() const { return steps_; }
  Particles& particles() { return scene_.particles; }
  Barriers& barriers() { return scene_.barriers; }
  Interactions& interactions() { return *interactions_; }
  const TrapezoidalIntegrator& trapezoidal() const { return trapezoidal_; }  // its predictor's history
  const Inlets* inlets() const { return inlets_.get(); }                     // null without [[inlet]]
  const Sinks* sinks() const { return sinks_.get(); }                        // null without [[sink]]
  const Model& model() const { return scene_.model; }
  Model& model() { return scene_.model; }  // a material edited between steps acts at the next step

 private:
  // NaN / infinity, energy jumps, domain exits after a step of h (s).
  void check_state(const StepReport& rep, double h);
  void check_energy(const HealthScan& s);
  void check_overlap(const OverlapReport& r);  // r: the deepest contact over all ranks
  struct Fastest {
    double v2 = 0.0;  // m^2/s^2, squared speed
    std::int64_t id = -1;
    int rank = -1;  // rank that holds it (several ranks; -1 on one)
  };
  // The k fastest particles over all ranks, fastest first (collective).
  std::vector<Fastest> fastest(std::size_t k) const;
  void record_state(const HealthScan& s);       // the balance and active energy into record_
  void record_overlap(const OverlapReport& r);  // r into record_ when it is the deepest yet
  void remove_outside();                        // domain.on_exit: stop or remove
  void remove_in_sinks();                       // [[sink]]: the particles in a sink, between steps
  void insert_from_inlets();                    // [[inlet]]: the particles due, between steps
  // Removes the particles whose keep[i] is 0: removed.csv, their energy into the balance, the
  // others' contact history kept, the rates re-evaluated; exits: domain exits (counted, one
  // progress line each), else a sink's. A clump body goes whole (all its members when one is
  // marked; its energy once). Collective on several ranks.
  void remove_marked(std::vector<char> keep, bool exits);
  ParticleTotals totals() const;                      // the sums over every rank's particles for the global log
  void log_row(GlobalLogRow row);                     // a global log row, with the inlets' and sinks' columns
  std::string open_system_summary() const;            // the inlets' and sinks' line for stderr ("" = none)
  void summarise_open_system(RunSummary& sum) const;  // its totals for the end-of-run verdict
  // J, mechanical energy + cumulative dissipation + what removed particles took along, from the
  // scan of the particles.
  double energy_balance(const HealthScan& s) const;

  // --- several ranks (simulation_decomposed.cpp) ---
  void decompose(const Communicator& comm);  // keeps this rank's particles, splits the work
  // The totals after a step over all ranks (sim/step_collective.hpp; one collective on several
  // ranks, this rank's own on one), kept for stats() and particle_count(): the interaction
  // statistics, the particle count, the scan (this rank's: s) and the deepest contact; on several
  // ranks also the stop signal and the particle snapshots due after a step of h (s; h < 0: none).
  const StepCollective& reduce_step(const HealthScan& s, double h);
  // The statistics of the last evaluation over all ranks (as of the last reduce_step).
  const InteractionStats& stats() const;
  // Every rank's particles in id order on rank 0 (collective; empty on the other ranks).
  Particles gathered();
  // The particle snapshots due after a step of h (s) now, on every rank: as decided with the
  // step's totals when they were for this step, else decided now by rank 0 (collective).
  ParticleSnapshotsDue particles_due(double h, bool force);
  // This rank's piece of particle VTU snapshot `index` (io/pvtu_writer.hpp); returns when every
  // rank's is complete (collective).
  void write_piece(std::uint64_t index);
  // Every rank's particles that reach into an inlet's volume (Inlets::reach), in id order, on
  // every rank (collective), and the particles of `fresh` this rank's brick holds.
  Particles near_inlets();
  void keep_own(Particles& fresh) const;
  std::size_t particle_count() const { return comm_ ? step_collective_.particles : scene_.particles.size(); }
  void snapshots(double h, bool force);  // the snapshot outputs due after a step of h (s)
  // Every rank's bonds in id order on rank 0 (collective; empty on the other ranks).
  std::vector<BondRecord> gathered_bonds() const;
  // The bonds' breaks recorded since the last call, in (time, ids) order, written to
  // bonds_broken.csv and kept for take_bond_breaks. Several ranks: collective; gathered on rank 0
  // when the last reduce_step counted any, or always with `always`.
  void collect_bond_breaks(bool always);
  // The lowest id of a particle with a non-finite state and the rank holding it, on every rank
  // (collective); id -1 if none.
  std::pair<std::int64_t, int> first_nonfinite() const;
  bool root() const { return comm_ == nullptr || comm_->rank() == 0; }

  // The scene as given, before any step: checkpoints carry it, a resume compares it. Declared
  // before scene_ so that it is taken from the constructor's argument before that is moved.
  SceneFingerprint fingerprint_;
  Scene scene_;
  RunOptions options_;
  const Communicator* comm_ = nullptr;  // several ranks; null in a one-rank run
  StepCollective step_collective_;      // the last reduce_step()'s
  // s, the time and step length of the particle snapshot decision in step_collective_ (h < 0: none).
  double snapshots_time_ = 0.0, snapshots_h_ = -1.0;
  std::unique_ptr<Interactions> interactions_;
  TrapezoidalIntegrator trapezoidal_;
  VerletIntegrator verlet_;
  std::unique_ptr<OutputManager> output_;
  std::unique_ptr<AnalysisOutputs> analysis_;  // contact snapshots, [[coarse_grain]] (null without)
  bool analysis_recording_ = false;            // analysis_ turned contact recording on for this step
  std::unique_ptr<Progress> progress_;         // set while run() runs
  std::unique_ptr<Inlets> inlets_;             // null without [[inlet]]
  std::unique_ptr<Sinks> sinks_;               // null without [[sink]]
  double time_ = 0.0;                          // s
  std::uint64_t steps_ = 0;
  // The time after a step of h: time_ = clock_time_ + (steps_ - clock_step_) * clock_dt_ while the
  // steps keep their length (a function of the step count: no round-off accumulates, a run in
  // parts or resumed is the same run); a step of another length starts the count again at its
  // start. Adaptive steps add their length (clock_dt_ NaN). Not in the checkpoint: a resume counts
  // from t = 0 when the checkpoint's time is steps * time.dt, else from the checkpoint.
  void advance_clock(double h, bool adaptive);
  double round_off(double end) const;  // s, how far from `end` the time still counts as there
  double clock_time_ = 0.0;            // s
  std::uint64_t clock_step_ = 0;
  double clock_dt_ = 0.0;  // s
  double last_h_ = 0.0;    // s, the length of the last accepted step
  std::uint64_t evaluations_ = 0;
  std::uint64_t redone_ = 0;     // adaptive steps redone with a smaller dt
  double dt_ = 0.0;              // s, step the next adaptive step tries
  double last_balance_ = 0.0;    // J, energy_balance() after the previous step
  double last_active_ = 0.0;     // J, active_energy (kinetic + rotational + |elastic|) after the previous step
  bool energy_checked_ = false;  // last_balance_ / last_active_ are set
  std::size_t removed_ = 0;
  std::uint64_t balance_rows_ = 0;      // load-balance measurements written to balance.csv
  std::vector<BondBreak> bond_breaks_;  // collected since the last take_bond_breaks (keep_bond_breaks)
  RunRecord record_;                    // for the end-of-run summary
  bool initialized_ = false;
  bool started_ = false;                     // start() ran: outputs open, first snapshots written
  StepReport last_;                          // the report of the last step()
  std::uint64_t first_step_ = 0;             // steps_ when start() ran
  bool resumed_ = false;                     // state loaded from a checkpoint
  std::vector<char> resume_output_state_;    // OutputManager series from the checkpoint
  std::vector<char> resume_analysis_state_;  // AnalysisOutputs series from the checkpoint (empty: none)
};

}  // namespace mpdem
