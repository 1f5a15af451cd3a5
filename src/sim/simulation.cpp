#include "sim/simulation.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>

#include "integrate/adaptive_step.hpp"
#include "integrate/integrator_policy.hpp"
#include "model/material_variants.hpp"
#include "integrate/energy_balance.hpp"
#include "core/atomic_file.hpp"
#include "output/output_manager.hpp"
#include "contact/particle_contacts.hpp"
#include "output/progress.hpp"
#include "parallel/gather.hpp"
#include "core/input_error.hpp"
#include "output/analysis_outputs.hpp"
#include "sim/inlets.hpp"
#include "core/run_error.hpp"
#include "sim/sinks.hpp"
#include "sim/stop_signal.hpp"

namespace mpdem {

std::filesystem::path output_dir_for(const Scene& scene, const RunOptions& options) {
  if (!options.output_dir.empty()) return options.output_dir;
  return scene.dir / scene.model.params.output.dir;
}

namespace {
// Every particle and element gets the material of its own constants (scenes built in code may
// set them per particle), before the contact laws index their tables by material.
Scene& with_materials_by_index(Scene& scene) {
  resolve_material_variants(scene.model, scene.particles, scene.barriers, scene.file.string());
  return scene;
}
// The log's inlet and sink columns, in GlobalLogRow::open_system's order.
std::vector<std::string> open_system_log_columns(const Params& prm) {
  std::vector<std::string> c = Inlets::log_columns(prm);
  for (std::string& s : Sinks::log_columns(prm)) c.push_back(std::move(s));
  return c;
}

}  // namespace

Simulation::Simulation(Scene&& scene, RunOptions options)
    : fingerprint_(fingerprint_scene(scene)), scene_(std::move(with_materials_by_index(scene))),
      options_(std::move(options)),
      interactions_(std::make_unique<Interactions>(scene_.model, scene_.particles, scene_.barriers,
                                                   integrator_policy(scene_.model.params))),
      trapezoidal_(scene_.model), verlet_(scene_.model), clock_dt_(scene_.model.params.time.dt),
      dt_(scene_.model.params.time.dt) {
  // The inlets first: their first id follows every particle of the scene, whichever rank holds it.
  if (!scene_.model.params.inlets.empty()) inlets_ = std::make_unique<Inlets>(scene_.model, scene_.particles);
  if (!scene_.model.params.sinks.empty()) sinks_ = std::make_unique<Sinks>(scene_.model);
  if (const Communicator& comm = options_.comm ? *options_.comm : Communicator::world(); !comm.serial())
    decompose(comm);
}

Simulation::~Simulation() = default;

void Simulation::initialize() {
  if (initialized_) return;
  interactions_->force_rebuild(scene_.particles, scene_.barriers, true);  // spatial order from the start
  // Rates at t = 0; commit with dt = 0 stores each contact's tangential velocity, no increment.
  interactions_->evaluate(scene_.particles, scene_.barriers, EvalRequest{time_, 0.0, 1.0, true});
  ++evaluations_;
  initialized_ = true;
  const Params& prm = scene_.model.params;
  const StepCollective& t = reduce_step(scan_state(scene_.particles, prm.fields, prm.domain), -1.0);
  check_energy(t.scan);  // the reference for the first step
  record_state(t.scan);  // the start of the run's drift
  record_overlap(t.deepest);
}

StepReport Simulation::advance(double dt) {
  initialize();
  interactions_->prepare_step(scene_.particles, scene_.barriers, dt);
  const Params& prm = scene_.model.params;
  if (!prm.checks.energy_ledger) {
    // Without the ledger the contacts' energies serve the log's `elastic` only: computed for a
    // step that writes a row (every log_every, and the run's last, which finish() logs).
    const auto every = static_cast<std::uint64_t>(std::max(prm.output.log_every, 1));
    const bool row = (steps_ + 1) % every == 0 || !(time_ + 2.0 * dt < prm.time.duration);
    interactions_->particle_contacts().compute_energies(row);
  }
  StepReport rep;
  if (prm.time.integrator == Integrator::Verlet) {
    rep = verlet_.step(scene_.particles, scene_.barriers, *interactions_, time_, dt);
  } else {
    rep = trapezoidal_.step(scene_.particles, scene_.barriers, *interactions_, time_, dt, prm.time.max_iterations);
    if (!rep.converged) {
      evaluations_ += static_cast<std::uint64_t>(rep.evaluations);
      throw RunError(fmt::format(
          "the fixed-point iteration did not converge within {} iterations at step {} (t = {:.9g} s, dt = {:.3g} s): "
          "field '{}' error {:.3g} > tolerance; largest change at particle id {}. Reduce time.dt (the contraction "
          "factor grows like (phi dt)^2 / m) or raise time.max_iterations.",
          prm.time.max_iterations, steps_ + 1, time_, dt, kFieldNames[rep.worst_field], rep.last_error[rep.worst_field],
          rep.worst_particle));
    }
  }
  evaluations_ += static_cast<std::uint64_t>(rep.evaluations);
  advance_clock(dt, false);
  check_state(rep, dt);
  return rep;
}

void Simulation::advance_clock(double h, bool adaptive) {
  if (adaptive || h != clock_dt_) {  // another step length: count its steps from this one's start
    clock_time_ = time_;
    clock_step_ = steps_;
    clock_dt_ = adaptive ? std::numeric_limits<double>::quiet_NaN() : h;
  }
  ++steps_;
  last_h_ = h;
  time_ = adaptive ? time_ + h : clock_time_ + static_cast<double>(steps_ - clock_step_) * h;
}

double end_round_off(double end, double dt) {
  const double ulps = std::isfinite(end) ? 8.0 * std::numeric_limits<double>::epsilon() * std::abs(end) : 0.0;
  return 1e-9 * dt + ulps;
}

std::uint64_t fixed_step_count(double duration, double dt) {
  const double n = std::ceil(duration / dt);
  if (!(n >= 1.0)) return 0;
  // ceil may land one above when duration / dt rounds up past a whole number.
  const bool one_less = (n - 1.0) * dt >= duration - end_round_off(duration, dt);
  return static_cast<std::uint64_t>(one_less ? n - 1.0 : n);
}

double Simulation::round_off(double end) const { return end_round_off(end, scene_.model.params.time.dt); }

bool Simulation::reached(double end) const { return time_ >= end - round_off(end); }

StepReport Simulation::advance_adaptive(double limit) {
  initialize();
  // Once for all tries: a redone step is shorter and starts from the same state.
  interactions_->prepare_step(scene_.particles, scene_.barriers, std::min(dt_, limit));
  const Params& prm = scene_.model.params;
  for (;;) {
    const double h = std::min(dt_, limit);
    StepReport rep = trapezoidal_.step(scene_.particles, scene_.barriers, *interactions_, time_, h,
                                       prm.time.desired_iterations);
    evaluations_ += static_cast<std::uint64_t>(rep.evaluations);
    const double factor = step_factor(rep, prm);
    if (rep.converged) {
      advance_clock(h, true);
      // A step shortened to land on `limit` says nothing about the step to take next.
      if (h == dt_) dt_ = std::clamp(factor * h, prm.time.dt_min, prm.time.dt_max);
      check_state(rep, h);
      return rep;
    }
    if (h <= prm.time.dt_min * (1.0 + 1e-12))
      throw RunError(fmt::format(
          "the fixed-point iteration did not converge within time.desired_iterations = {} at the smallest step "
          "time.dt_min = {:.3g} s (step {}, t = {:.9g} s): field '{}' error {:.3g}; largest change at particle id {}. "
          "Reduce time.dt_min or loosen [tolerance] {}.",
          prm.time.desired_iterations, prm.time.dt_min, steps_ + 1, time_, kFieldNames[rep.worst_field],
          rep.last_error[rep.worst_field], rep.worst_particle, kFieldNames[rep.worst_field]));
    ++redone_;
    // Phi < 1 here (eps_K > TOL at K = K_D); the cap guarantees progress towards dt_min.
    constexpr double kLargestRedoFactor = 0.9;
    dt_ = std::max(prm.time.dt_min, std::min(factor, kLargestRedoFactor) * h);
  }
}

void Simulation::check_state(const StepReport& rep, double h) {
  Particles& p = scene_.particles;
  const Params& prm = scene_.model.params;
  // One pass (or none, when the integrator fused it into its own); culprits searched only if needed.
  const StepCollective& totals = reduce_step(
      rep.scanned ? rep.scan : scan_state(p, prm.fields, prm.domain, prm.checks.energy_ledger), h);
  const HealthScan scan = totals.scan;
  const OverlapReport deepest = totals.deepest;
  if (scan.nonfinite > 0 && comm_) {
    const auto [id, rank] = first_nonfinite();
    throw RunError(fmt::format("non-finite state of particle id {}{} at step {} (t = {:.9g} s). The run is unstable; "
                               "reduce time.dt.",
                               id, rank_note(comm_, rank), steps_, time_));
  }
  if (scan.nonfinite > 0)
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (!finite_state(p, i))
        throw RunError(fmt::format("non-finite state of particle id {} at step {} (t = {:.9g} s): x = ({}, {}, {}), "
                                   "v = ({}, {}, {}). The run is unstable; reduce time.dt.",
                                   p.id[i], steps_, time_, p.x[i].x, p.x[i].y, p.x[i].z, p.v[i].x, p.v[i].y, p.v[i].z));
    }
  check_overlap(deepest);
  check_energy(scan);
  record_state(scan);
  if (scan.outside > 0) remove_outside();
  if (sinks_) remove_in_sinks();
  if (inlets_) insert_from_inlets();
}

void Simulation::log_row(GlobalLogRow row) {
  if (inlets_) inlets_->log_values(row.open_system);
  if (sinks_) sinks_->log_values(row.time, row.open_system);
  const ParticleTotals t = totals();
  if (output_) output_->global_log(row, t, stats());
}

ParticleTotals Simulation::totals() const {
  ParticleTotals t = particle_totals(scene_.model, scene_.particles);
  if (comm_) {  // reduced, never gathered: a log row costs the same on any number of ranks
    double v[] = {t.energy.kinetic, t.energy.rotational, t.energy.potential, t.electric,
                  t.count,          t.thermal,           t.bodies,           t.members};
    comm_->sum(v);
    t = {{v[0], v[1], v[2]}, v[3], v[4], v[5], v[6], v[7]};
  }
  return t;
}

std::vector<std::pair<std::string, double>> Simulation::log_values() const {
  GlobalLogRow row{steps_, time_, dt_, &last_, evaluations_, redone_, removed_, {}};
  row.bonds_broken_before = output_ ? output_->bonds_broken_logged() : 0;
  if (inlets_) inlets_->log_values(row.open_system);
  if (sinks_) {  // a copy: the sinks' rates are measured between rows of the log file
    Sinks copy = *sinks_;
    copy.log_values(time_, row.open_system);
  }
  const GlobalLogLayout layout(scene_.model, scene_.barriers, open_system_log_columns(scene_.model.params));
  const std::vector<double> v = layout.values(row, totals(), stats());
  std::vector<std::pair<std::string, double>> out;
  for (std::size_t k = 0; k < v.size(); ++k) out.emplace_back(layout.columns()[k], v[k]);
  return out;
}

void Simulation::snapshots(double h, bool force) {
  if (!comm_) {
    const Bonds* bonds = interactions_->bonds();
    output_->snapshots(time_, h, scene_.particles, scene_.barriers, force,
                       bonds ? bonds->records() : std::span<const BondRecord>{});
    return;
  }
  const ParticleSnapshotsDue due = particles_due(h, force);
  // A VTU snapshot: every rank writes its piece, rank 0 their .pvtu index (output_->snapshots). A
  // CSV or bond snapshot gathers the particles (and the bonds) to rank 0. The barriers are the same
  // on every rank (their loads summed): rank 0 writes them as they are.
  if (due.vtu) write_piece(due.vtu_index);
  const Particles all = due.gather() ? gathered() : Particles{};
  const std::vector<BondRecord> bonds = due.bonds ? gathered_bonds() : std::vector<BondRecord>{};
  if (output_) output_->snapshots(time_, h, all, scene_.barriers, force, bonds);
}

RunSummary Simulation::run() {
  start();
  const double end = scene_.model.params.time.duration;
  while (!reached(end)) step(end);
  return finish();
}

void Simulation::start() {
  if (started_) return;
  const Params& prm = scene_.model.params;
  const bool out = options_.write_output;  // on every rank; rank 0 writes, the others their particle pieces
  if (out && root()) {
    output_ = std::make_unique<OutputManager>(
        scene_.model, output_dir_for(scene_, options_), scene_.barriers, open_system_log_columns(prm),
        resumed_ ? std::optional<double>(time_) : std::nullopt, comm_ ? comm_->size() : 1);
    if (!resume_output_state_.empty()) {
      BinaryReader r(resume_output_state_.data(), resume_output_state_.size());
      output_->restore(r);
    }
  }
  if (out && AnalysisOutputs::wanted(prm)) {  // on every rank: each sample gathers on rank 0
    analysis_ = std::make_unique<AnalysisOutputs>(scene_.model, output_dir_for(scene_, options_),
                                                  resumed_ ? std::optional<double>(time_) : std::nullopt, comm_);
    if (!resume_analysis_state_.empty()) {
      BinaryReader r(resume_analysis_state_.data(), resume_analysis_state_.size());
      analysis_->restore(r);
    }
  }
  initialize();
  collect_bond_breaks(false);
  if (out && !resumed_) {
    snapshots(prm.time.dt, true);
    log_row({0, time_, prm.time.dt, nullptr, evaluations_, 0, removed_, {}});
  }
  if (options_.stop_on_signal) install_stop_handlers();
  first_step_ = steps_;
  progress_ = std::make_unique<Progress>(prm.time.duration, prm.output.progress_every, options_.progress && root(),
                                         time_, steps_);
  started_ = true;
}

void Simulation::step(double end) {
  start();
  const Params& prm = scene_.model.params;
  const bool out = options_.write_output;
  const bool adaptive = prm.time.adaptive && prm.time.integrator == Integrator::Trapezoidal;
  // The step to take (an adaptive step may turn out shorter); the last one ends exactly at `end`,
  // unless it ends within round-off of it: then it is taken whole, as every other step.
  const double whole = adaptive ? dt_ : prm.time.dt;
  const double left = end - time_;
  const bool cut = left < whole - round_off(end);
  const double planned = cut ? left : whole;
  if (analysis_) {  // the contact list of a step that an analysis output samples
    ParticleContacts& pc = interactions_->particle_contacts();
    if (!pc.recording() && analysis_->needs_contacts(time_ + planned, planned, prm.time.duration)) {
      pc.record_contacts(true);
      analysis_recording_ = true;
    }
  }
  const bool before_end = !reached(prm.time.duration);
  if (adaptive) last_ = advance_adaptive(cut ? left : std::max(left, whole));
  else last_ = advance(planned);
  const double h = last_h_;
  collect_bond_breaks(false);
  if (output_) output_->accumulate_barrier_loads(scene_.barriers, h);
  if (out) {
    // The step that reaches the run's end writes the end's snapshots (finish() finds them
    // written), before a checkpoint of this step: a run resumed from it continues their series.
    snapshots(h, before_end && reached(prm.time.duration));
    if (steps_ % static_cast<std::uint64_t>(prm.output.log_every) == 0)
      log_row({steps_, time_, h, &last_, evaluations_, redone_, removed_, {}});
  }
  if (analysis_) {
    analysis_->after_step(time_, h, prm.time.duration, reached(prm.time.duration), scene_.particles, scene_.barriers,
                          *interactions_);
    if (analysis_recording_) interactions_->particle_contacts().record_contacts(false);
    analysis_recording_ = false;
  }
  if (output_ && interactions_->balance_measurements() != balance_rows_) {
    balance_rows_ = interactions_->balance_measurements();
    output_->balance(
        {time_, steps_, comm_->size(), interactions_->imbalance(), interactions_->moved_at_last_measurement()});
  }
  const auto& st = stats();
  progress_->update(time_, steps_, st.contacts_pp + st.contacts_pb, particle_count(), interactions_->imbalance(),
                    interactions_->cohesive() ? std::optional<std::uint64_t>(st.bridges) : std::nullopt,
                    interactions_->bonds() ? std::optional(std::array{st.bonds_intact, st.bonds_broken})
                                           : std::nullopt);
  if ((inlets_ || sinks_) && progress_->summary_due()) progress_->summary(open_system_summary());
  const auto every = static_cast<std::uint64_t>(prm.output.checkpoint_every);
  const std::filesystem::path dir = output_dir_for(scene_, options_);
  if (out && every > 0 && steps_ % every == 0) {  // (collective on several ranks)
    write_checkpoint(dir / "checkpoint.bin");
    flush_outputs();
  }
  if (!options_.stop_on_signal) return;
  if (const int sig = comm_ ? step_collective_.stop : stop_signal()) {
    std::filesystem::path ck;
    if (out) {
      ck = dir / "checkpoint.bin";
      write_checkpoint(ck);
      flush_outputs();
    }
    throw Interrupted(sig, time_, steps_, ck);
  }
}

void Simulation::flush_outputs() {
  if (output_) output_->flush();
  if (analysis_) analysis_->flush();
}

RunSummary Simulation::finish() {
  start();
  const Params& prm = scene_.model.params;
  collect_bond_breaks(true);
  if (options_.write_output) {
    snapshots(prm.time.dt, true);
    if (steps_ % static_cast<std::uint64_t>(prm.output.log_every) != 0)
      log_row({steps_, time_, dt_, &last_, evaluations_, redone_, removed_, {}});
    if (output_) output_->flush();
    if (analysis_) analysis_->flush();
  }
  if (inlets_ || sinks_) progress_->summary(open_system_summary());  // the final totals
  progress_->finish(time_, steps_);
  RunSummary sum{time_, steps_, steps_ - first_step_, evaluations_, removed_, record_, prm.checks.energy_drift, ""};
  summarise_open_system(sum);
  // Work and potential the balance leaves out make its drift meaningless as a measure of the step.
  if (prm.near_field.cutoff > 0.0) sum.drift_unchecked = "the near field's potential is not in the balance";
  sum.booked = prm.checks.energy_ledger;
  if (output_) {
    // Kept beside the results, where a warning on stderr is easily lost; none: an earlier one is stale.
    const std::string warning = drift_warning(sum);
    const std::filesystem::path file = output_->dir() / "warnings.txt";
    if (!warning.empty()) write_file_atomically(file, [&](std::ostream& os) { os << warning << "\n"; });
    else std::filesystem::remove(file);
  }
  return sum;
}

}  // namespace mpdem
