#include "python/py_simulation.hpp"

#include <fmt/core.h>
#include <omp.h>

#include <chrono>
#include <cmath>
#include <limits>

#include "output/global_log.hpp"
#include "core/input_error.hpp"
#include "io/output_folder.hpp"
#include "model/derived_limits.hpp"
#include "model/particle_defaults.hpp"
#include "parallel/communicator.hpp"
#include "python/particle_arrays.hpp"
#include "output/contact_list.hpp"

namespace mpdem::python {

namespace {
// s of wall time between two looks at Python's pending signals while stepping: each look takes
// the GIL, which a busy Python thread may hold for its whole switch interval (5 ms).
constexpr double kSignalCheck = 0.05;

double wall_seconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

RunOptions run_options(const SimulationOptions& o) {
  RunOptions r;
  r.output_dir = o.output_dir;
  r.progress = o.progress;
  r.write_output = o.write_output;
  r.comm = &Communicator::single();  // one process: the module does not start MPI
  r.stop_on_signal = false;          // Python keeps its own handlers; check_signals asks them
  r.keep_bond_breaks = true;         // sim.bonds.new_breaks()
  return r;
}

// OpenMP's thread count is a setting of the calling thread: set it on the thread that steps.
void use_threads(int threads) {
  if (threads > 0) omp_set_num_threads(threads);
}
}  // namespace

PySimulation::PySimulation(Scene&& scene, const SimulationOptions& options)
    : sim_(std::make_unique<Simulation>(std::move(scene), run_options(options))), options_(options) {
  if (!options.resume.empty()) sim_->resume_from(options.resume);
  // Refused here, at the call, rather than as a raw filesystem error at the first output.
  if (options.write_output) ensure_output_folder(output_dir(), "choose another with output_dir=");
  last_check_ = wall_seconds();
}

void PySimulation::stop_cleanly() {
  if (options_.write_output) {
    sim_->write_checkpoint(output_dir() / "checkpoint.bin");
    sim_->flush_outputs();
  }
}

void PySimulation::check_signals(bool now) {
  const double t = wall_seconds();
  if (!now && t - last_check_ < kSignalCheck) return;
  last_check_ = t;
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) {
    const py::error_already_set error;  // takes the pending KeyboardInterrupt
    {
      py::gil_scoped_release nogil;
      stop_cleanly();
    }
    throw error;
  }
}

void PySimulation::step_flushing(double end) {
  try {
    sim_->step(end);
  } catch (const std::exception&) {
    sim_->flush_outputs();  // what was written before the failure stays readable
    throw;
  }
}

double PySimulation::step_limit() const {
  // Whole steps of the scene's dt, as `mpdem run` takes them, so that a run in parts is the same
  // run; only the scene's end cuts a step short.
  const double end = end_time();
  return sim_->reached(end) ? std::numeric_limits<double>::infinity() : end;
}

void PySimulation::finish_if_at_end() {
  if (!finished_ && sim_->reached(end_time())) {
    sim_->finish();
    finished_ = true;
  } else {
    sim_->flush_outputs();
  }
}

bool PySimulation::run(std::optional<double> end, const py::object& callback, long every) {
  const double until = end.value_or(end_time());
  const bool calls = !callback.is_none() && every > 0;
  py::gil_scoped_release nogil;
  use_threads(options_.threads);
  sim_->start();
  while (!sim_->reached(until)) {
    step_flushing(step_limit());
    if (calls && sim_->steps() % static_cast<std::uint64_t>(every) == 0) {
      py::gil_scoped_acquire gil;
      try {
        callback();
      } catch (py::error_already_set&) {
        // The traceback goes to the caller; the outputs stay complete up to this step.
        py::gil_scoped_release again;
        sim_->flush_outputs();
        throw;
      }
      last_check_ = wall_seconds();  // the callback ran Python: pending signals were handled
    } else {
      check_signals(false);
    }
  }
  finish_if_at_end();
  return finished_;
}

void PySimulation::step(long n) {
  py::gil_scoped_release nogil;
  use_threads(options_.threads);
  sim_->start();
  for (long k = 0; k < n; ++k) {
    step_flushing(step_limit());
    if (k + 1 < n) check_signals(false);
  }
  finish_if_at_end();
}

void PySimulation::close() {
  py::gil_scoped_release nogil;
  if (!finished_) {
    sim_->finish();
    finished_ = true;
  }
}

namespace {
using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;

// arrays[key] as n rows of `width` doubles (width 1: n values); none when absent.
std::optional<Doubles> rows(const py::dict& arrays, const char* key, std::size_t n, py::ssize_t width) {
  if (!arrays.contains(key) || arrays[key].is_none()) return std::nullopt;
  auto a = Doubles::ensure(arrays[key]);
  const bool ok = a && (width == 1 ? a.ndim() == 1 && a.shape(0) == static_cast<py::ssize_t>(n)
                                   : a.ndim() == 2 && a.shape(0) == static_cast<py::ssize_t>(n) && a.shape(1) == width);
  if (!ok)
    throw InputError("", 0, key,
                     "expected " + std::to_string(n) + (width == 1 ? " values" : " rows of 3 values") +
                         " (one per new particle)");
  for (py::ssize_t k = 0; k < a.size(); ++k)
    if (!std::isfinite(a.data()[k]))
      throw InputError("", 0, key, fmt::format("values must be finite (row {}: {})", k / width, a.data()[k]));
  return a;
}

// The mass, inertia and time scales a radius gives with its material must be usable, as the
// particle CSV reader requires (model/derived_limits.hpp).
void check_new_particle(const Material& m, double r, std::size_t row, bool thermal) {
  std::string p = mass_problem(r, m.density);
  if (p.empty()) p = time_scale_problem(r, m.density, m.young, m.poisson);
  if (p.empty() && thermal) p = thermal_mass_problem(r, m.density, m.heat_capacity);
  if (!p.empty()) throw InputError("", 0, "radius", fmt::format("{} (row {}, material '{}')", p, row, m.name));
}

Vec3 row3(const Doubles& a, std::size_t i) {
  const double* d = a.data() + 3 * i;
  return {d[0], d[1], d[2]};
}
}  // namespace

py::array_t<std::int64_t> PySimulation::add_particles(const py::dict& arrays) {
  if (!arrays.contains("position")) throw InputError("", 0, "position", "required: (N, 3) m");
  const auto x = Doubles::ensure(arrays["position"]);
  if (!x || x.ndim() != 2 || x.shape(1) != 3) throw InputError("", 0, "position", "expected an (N, 3) array");
  const auto n = static_cast<std::size_t>(x.shape(0));
  const auto position = rows(arrays, "position", n, 3);
  const auto radius = rows(arrays, "radius", n, 1);
  if (!radius) throw InputError("", 0, "radius", "required: (N,) m");
  const auto velocity = rows(arrays, "velocity", n, 3), spin = rows(arrays, "angular_velocity", n, 3);
  const auto temperature = rows(arrays, "temperature", n, 1), charge = rows(arrays, "charge", n, 1);
  const auto material = rows(arrays, "material", n, 1);
  std::optional<py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>> id;
  if (arrays.contains("id") && !arrays["id"].is_none()) {
    id = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(arrays["id"]);
    if (!*id || id->ndim() != 1 || id->shape(0) != static_cast<py::ssize_t>(n))
      throw InputError("", 0, "id", "expected " + std::to_string(n) + " integer ids (one per new particle)");
  }
  const auto fixed = rows(arrays, "fixed", n, 1);
  const auto& materials = sim_->model().materials;
  Particles fresh;
  fresh.reserve(n);
  std::int64_t next = sim_->next_free_id();
  const bool thermal = sim_->model().params.analysis.thermal;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = radius->data()[i];
    if (!(r > 0.0)) throw InputError("", 0, "radius", fmt::format("must be > 0, got {} (row {})", r, i));
    const double m = material ? material->data()[i] : 0.0;
    if (m != std::floor(m) || m < 0.0 || m >= static_cast<double>(materials.size()))
      throw InputError("", 0, "material", fmt::format("not a material of the scene: {} (row {})", m, i));
    const auto mat = static_cast<int>(m);
    check_new_particle(materials[static_cast<std::size_t>(mat)], r, i, thermal);
    if (temperature && temperature->data()[i] < 0.0)
      throw InputError("", 0, "temperature", fmt::format("must be >= 0 K, got {} (row {})", temperature->data()[i], i));
    if (fixed && fixed->data()[i] != 0.0 && fixed->data()[i] != 1.0)
      throw InputError("", 0, "fixed",
                       fmt::format("expected 0 (free) or 1 (fixed), got {} (row {})", fixed->data()[i], i));
    const std::int64_t pid = id ? id->data()[i] : next++;
    fresh.add(pid, mat, r, materials[static_cast<std::size_t>(mat)].density, row3(*position, i),
              velocity ? row3(*velocity, i) : Vec3{});
    take_material_properties(fresh, i, materials[static_cast<std::size_t>(mat)]);
    if (spin) fresh.w[i] = row3(*spin, i);
    if (temperature) fresh.T[i] = temperature->data()[i];
    if (charge) fresh.charge[i] = charge->data()[i];
    if (fixed) fresh.fixed[i] = fixed->data()[i] != 0.0 ? 1 : 0;
  }
  py::array_t<std::int64_t> ids(static_cast<py::ssize_t>(n));
  std::copy(fresh.id.begin(), fresh.id.end(), ids.mutable_data());
  py::gil_scoped_release nogil;
  sim_->add_particles(std::move(fresh));
  return ids;
}

void PySimulation::remove_particles(const py::array_t<std::int64_t, py::array::forcecast>& ids) {
  std::vector<std::int64_t> v(ids.data(), ids.data() + ids.size());
  py::gil_scoped_release nogil;
  sim_->remove_particles(v);
}

void PySimulation::add_loads(const py::array_t<std::int64_t, py::array::forcecast>& ids, const Doubles& force,
                             const Doubles& torque) {
  const auto n = static_cast<std::size_t>(ids.size());
  for (const auto* a : {&force, &torque})
    if (a->ndim() != 2 || a->shape(0) != static_cast<py::ssize_t>(n) || a->shape(1) != 3)
      throw py::value_error("force and torque need " + std::to_string(n) + " rows of 3 values (one per id)");
  (void)indices_of(sim_->particles(), ids);  // an unknown id: ValueError
  std::vector<std::int64_t> id(ids.data(), ids.data() + n);
  std::vector<Vec3> f(n), t(n);
  for (std::size_t k = 0; k < n; ++k) {
    f[k] = row3(force, k);
    t[k] = row3(torque, k);
    for (const auto& [key, v] : {std::pair{"force", f[k]}, std::pair{"torque", t[k]}})
      if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        throw InputError("", 0, key, fmt::format("values must be finite (row {}, particle id {})", k, id[k]));
  }
  sim_->interactions().external_loads().set(id, f, t);
  sim_->state_changed();
}

void PySimulation::record_contacts(bool on) {
  recording_ = on;
  sim_->interactions().particle_contacts().record_contacts(on);
}

py::dict PySimulation::contacts() const {
  Interactions& in = sim_->interactions();
  if (!recording_)
    throw std::runtime_error(
        "contacts are not recorded: set sim.record_contacts = True before the steps whose contacts you want");
  if (in.particle_contacts().records().size() != in.search().pairs().num_pairs())
    throw std::runtime_error("no contacts recorded yet: take a step after sim.record_contacts = True");
  const std::vector<ContactEntry> list = contact_list(sim_->particles(), sim_->barriers(), in);
  const auto m = static_cast<py::ssize_t>(list.size());
  py::array_t<std::int64_t> first(m), second(m), element(m);
  py::array_t<double> point({m, py::ssize_t{3}}), normal({m, py::ssize_t{3}}), fn({m, py::ssize_t{3}}),
      ft({m, py::ssize_t{3}}), overlap(m);
  py::array_t<bool> sliding(m), touching(m), bridge(m);
  auto put = [](py::array_t<double>& a, py::ssize_t k, const Vec3& v) {
    double* d = a.mutable_data(k, 0);
    d[0] = v.x, d[1] = v.y, d[2] = v.z;
  };
  for (py::ssize_t k = 0; k < m; ++k) {
    const ContactEntry& e = list[static_cast<std::size_t>(k)];
    first.mutable_data()[k] = e.first;
    second.mutable_data()[k] = e.second;
    element.mutable_data()[k] = e.element;
    put(point, k, e.point);
    put(normal, k, e.normal);
    put(fn, k, e.normal_force);
    put(ft, k, e.tangential_force);
    overlap.mutable_data()[k] = e.overlap;
    sliding.mutable_data()[k] = e.sliding;
    touching.mutable_data()[k] = e.touching;
    bridge.mutable_data()[k] = e.bridge;
  }
  py::dict d;
  d["i"] = first;
  d["j"] = second;
  d["element"] = element;
  d["point"] = point;
  d["normal"] = normal;
  d["overlap"] = overlap;
  d["normal_force"] = fn;
  d["tangential_force"] = ft;
  d["sliding"] = sliding;
  d["touching"] = touching;
  d["bridge"] = bridge;
  if (!sim_->model().clumps.empty()) {  // the members' bodies, as the contact files name them
    py::array_t<std::int64_t> body_i(m), body_j(m);
    for (py::ssize_t k = 0; k < m; ++k) {
      body_i.mutable_data()[k] = list[static_cast<std::size_t>(k)].first_body;
      body_j.mutable_data()[k] = list[static_cast<std::size_t>(k)].second_body;
    }
    d["body_i"] = body_i;
    d["body_j"] = body_j;
  }
  return d;
}

py::list PySimulation::material_names() const {
  py::list out;
  for (const Material& m : sim_->model().materials) out.append(m.name);
  return out;
}

py::dict PySimulation::log() const {
  py::dict d;
  for (const auto& [name, value] : sim_->log_values()) d[py::str(name)] = value;
  return d;
}

void PySimulation::save(const std::filesystem::path& file) {
  py::gil_scoped_release nogil;
  sim_->initialize();  // the rates of the state being saved
  sim_->write_checkpoint(file);
}

std::filesystem::path PySimulation::output_dir() const { return sim_->output_dir(); }

}  // namespace mpdem::python
