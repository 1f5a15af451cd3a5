#pragma once
// PySimulation: the Simulation behind mpdem.Simulation (python/mpdem/simulation.py). Steps with
// the GIL released, calls Python back only between accepted steps, notices Ctrl-C within
// kSignalCheck of wall time and stops after the current step with complete outputs.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "sim/simulation.hpp"

namespace mpdem::python {

namespace py = pybind11;

struct SimulationOptions {
  int threads = 0;                   // OpenMP threads while stepping (0: OpenMP's default)
  std::filesystem::path output_dir;  // empty: the scene's [output] dir
  bool write_output = true;          // false: no files
  bool progress = false;             // the CLI's progress line on stderr
  std::filesystem::path resume;      // a checkpoint to continue from (empty: none)
};

class PySimulation {
 public:
  PySimulation(Scene&& scene, const SimulationOptions& options);

  // Steps until time `end` (s; none: the scene's [time] duration): whole steps of the scene's dt,
  // the first that reaches `end` (within 1e-9 dt) the last, only the scene's end cutting a step
  // short. Calls `callback()` with the GIL held after every `every` accepted steps (none: no
  // callback). Returns true when the run reached the scene's end, whose final outputs are then
  // written as the CLI writes them.
  bool run(std::optional<double> end, const py::object& callback, long every);
  void step(long n);  // n accepted steps (the last one may end at the scene's end time)

  double time() const { return sim_->time(); }
  double dt() const { return sim_->current_dt(); }
  double end_time() const { return sim_->model().params.time.duration; }
  std::uint64_t steps() const { return sim_->steps(); }
  std::uint64_t evaluations() const { return sim_->evaluations(); }
  py::dict log() const;
  void save(const std::filesystem::path& file);
  void close();  // the final outputs now, if the run never reached the scene's end
  std::filesystem::path output_dir() const;

  // Appends particles (mpdem.Simulation.add_particles; arrays checked, InputError naming the
  // array) and returns their ids; removes the particles `ids`.
  py::array_t<std::int64_t> add_particles(const py::dict& arrays);
  void remove_particles(const py::array_t<std::int64_t, py::array::forcecast>& ids);
  py::list material_names() const;
  // Loads added to the particles `ids` from now on (rows of (3,) N and N m; zero: removed).
  void add_loads(const py::array_t<std::int64_t, py::array::forcecast>& ids,
                 const py::array_t<double, py::array::c_style | py::array::forcecast>& force,
                 const py::array_t<double, py::array::c_style | py::array::forcecast>& torque);
  void clear_loads() { sim_->interactions().external_loads().clear(); }
  // The contact list of the last evaluation as numpy arrays (output/contact_list.hpp); recording of
  // the pair contacts is switched on by record_contacts(true) before the steps it is wanted for.
  py::dict contacts() const;
  void record_contacts(bool on);
  bool recording_contacts() const { return recording_; }

  Simulation& engine() { return *sim_; }
  // After the caller changed the state: the rates at the new state (Simulation::state_changed).
  void state_changed() { sim_->state_changed(); }

 private:
  // Between steps: Python's signal handlers (Ctrl-C) when due; throws py::error_already_set
  // after flushing the outputs (and writing a checkpoint beside them) if one raised.
  void check_signals(bool now);
  void stop_cleanly();
  void step_flushing(double end);
  double step_limit() const;  // s, where the next step must end at the latest
  void finish_if_at_end();  // the final outputs at the scene's end, else the outputs flushed  // Simulation::step, the
                            // outputs flushed if it throws
  std::unique_ptr<Simulation> sim_;
  SimulationOptions options_;
  bool recording_ = false;   // the pair contacts' forces are recorded at every evaluation
  bool finished_ = false;    // the scene's end was reached and its final outputs written
  double last_check_ = 0.0;  // s of wall time at the last signal check
};

}  // namespace mpdem::python
