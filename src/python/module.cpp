// mpdem._core: the engine for the Python package mpdem (python/mpdem/, docs/python.md). The
// package's Scene and Simulation classes are Python; this module loads scenes through the same
// reader as the CLI and steps them.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <array>
#include <cmath>

#include "check/scene_checks.hpp"
#include "core/input_error.hpp"
#include "python/barrier_groups.hpp"
#include "python/body_arrays.hpp"
#include "python/bond_arrays.hpp"
#include "python/particle_arrays.hpp"
#include "python/py_simulation.hpp"
#include "core/run_error.hpp"
#include "scene/scene_reader.hpp"

namespace py = pybind11;
using namespace mpdem;
using python::PySimulation;

namespace {

// The scene of a file, or of TOML text standing for `file` (called `name` in messages).
Scene load(const std::filesystem::path& file, const std::optional<std::string>& text, const std::string& name) {
  return text ? load_scene_text(*text, file, name) : load_scene(file);
}

// The problems `mpdem check` reports before a run, as (stops_run, message) pairs.
py::list check(const std::filesystem::path& file, const std::optional<std::string>& text, const std::string& name) {
  const Scene scene = load(file, text, name);
  py::list out;
  for (const SceneProblem& p : check_scene(scene)) out.append(py::make_tuple(p.stops_run, p.message));
  return out;
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "mpdem engine (use the mpdem package: mpdem.Scene, mpdem.Simulation)";
  m.attr("__version__") = MPDEM_VERSION;

  // mpdem.InputError(ValueError): bad input, with the file, line and key the message names.
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<RunError> run_error(m, "RunError", PyExc_RuntimeError);
  // (pybind11 takes a function of a std::exception_ptr by value)
  py::register_exception_translator([](std::exception_ptr p) {  // NOLINT(performance-unnecessary-value-param)
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      py::object err = py::handle(input_error.ptr())(e.what());
      err.attr("file") = e.file();
      err.attr("line") = e.line();
      err.attr("key") = e.key();
      PyErr_SetObject(input_error.ptr(), err.ptr());
    } catch (const RunError& e) {
      PyErr_SetString(run_error.ptr(), e.what());
    }
  });

  m.def(
      "parse", [](const std::filesystem::path& file) { (void)parse_scene_file(file); }, py::arg("file"),
      "Reads a scene file's tables (not its particle and barrier files); raises InputError for bad input.");
  m.def("check", &check, py::arg("file"), py::arg("text") = py::none(), py::arg("name") = "",
        "Loads a scene (from `file`, or from TOML `text` standing for `file`) and returns the problems "
        "`mpdem check` finds, as (stops_run, message) pairs. Raises InputError for bad input.");

  py::class_<PySimulation>(m, "Simulation")
      .def(py::init([](const std::filesystem::path& file, const std::optional<std::string>& text,
                       const std::string& name, int threads, const std::filesystem::path& output_dir, bool write_output,
                       bool progress, const std::filesystem::path& resume) {
             python::SimulationOptions o{threads, output_dir, write_output, progress, resume};
             return std::make_unique<PySimulation>(load(file, text, name), o);
           }),
           py::arg("file"), py::arg("text") = py::none(), py::arg("name") = "", py::arg("threads") = 0,
           py::arg("output_dir") = std::filesystem::path(), py::arg("write_output") = true, py::arg("progress") = false,
           py::arg("resume") = std::filesystem::path())
      .def("run", &PySimulation::run, py::arg("end") = py::none(), py::arg("callback") = py::none(),
           py::arg("every") = 1)
      .def("step", &PySimulation::step, py::arg("n") = 1)
      .def("close", &PySimulation::close)
      .def("save", &PySimulation::save, py::arg("file"))
      .def("log", &PySimulation::log)
      .def("add_particles", &PySimulation::add_particles, py::arg("arrays"))
      .def("remove_particles", &PySimulation::remove_particles, py::arg("ids"))
      .def("add_loads", &PySimulation::add_loads, py::arg("ids"), py::arg("force"), py::arg("torque"))
      .def("clear_loads",
           [](PySimulation& s) {
             s.clear_loads();
             s.state_changed();
           })
      .def_property_readonly("materials", &PySimulation::material_names)
      .def("contacts", &PySimulation::contacts)
      .def_property("record_contacts", &PySimulation::recording_contacts, &PySimulation::record_contacts)
      .def_property_readonly("barrier_groups",
                             [](PySimulation& s) { return python::group_names(s.engine().barriers()); })
      .def("group_load",
           [](PySimulation& s, const std::string& g) { return python::group_load(s.engine().barriers(), g); })
      .def("group_motion",
           [](PySimulation& s, const std::string& g) { return python::group_motion(s.engine().barriers(), g); })
      .def("set_group_velocity",
           [](PySimulation& s, const std::string& g, const std::array<double, 3>& v) {
             // The barriers move by their laws at every step: the new law acts from the next step on.
             python::set_group_velocity(s.engine().barriers(), g, {v[0], v[1], v[2]}, s.time());
           })
      .def_property(
          "gravity",
          [](PySimulation& s) {
            const Vec3 g = s.engine().model().params.fields.gravity;
            return std::array<double, 3>{g.x, g.y, g.z};
          },
          [](PySimulation& s, const std::array<double, 3>& g) {
            for (const double c : g)
              if (!std::isfinite(c)) throw InputError("", 0, "gravity.vector", "components must be finite");
            s.engine().model().params.fields.gravity = {g[0], g[1], g[2]};
            s.state_changed();
          })
      .def_property_readonly("time", &PySimulation::time)
      .def_property_readonly("dt", &PySimulation::dt)
      .def_property_readonly("end_time", &PySimulation::end_time)
      .def_property_readonly("steps", &PySimulation::steps)
      .def_property_readonly("evaluations", &PySimulation::evaluations)
      .def_property_readonly("output_dir", &PySimulation::output_dir)
      .def_property_readonly("count", [](PySimulation& s) { return s.engine().particles().size(); })
      .def("get",
           [](PySimulation& s, const std::string& name) { return python::id_ordered(s.engine().particles(), name); })
      .def("view",
           [](const py::object& self, const std::string& name) {
             return python::storage_view(self.cast<PySimulation&>().engine().particles(), name, self);
           })
      .def(
          "set",
          [](PySimulation& s, const std::string& name,
             const py::array_t<double, py::array::c_style | py::array::forcecast>& values, const py::object& ids) {
            python::set_array(s.engine().particles(), name, values, ids);
            s.state_changed();
          },
          py::arg("name"), py::arg("values"), py::arg("ids") = py::none())
      .def("bond_arrays", [](PySimulation& s) { return python::bond_arrays(s.engine()); })
      .def("new_bond_breaks", [](PySimulation& s) { return python::new_bond_breaks(s.engine()); })
      .def(
          "add_bond", [](PySimulation& s, std::int64_t a, std::int64_t b) { s.engine().add_bond(a, b); },
          py::arg("id_i"), py::arg("id_j"))
      .def_property_readonly("body_count", [](PySimulation& s) { return s.engine().particles().bodies.size(); })
      .def("body_get",
           [](PySimulation& s, const std::string& name) {
             return python::body_array(s.engine().model(), s.engine().particles(), name);
           })
      .def(
          "body_set",
          [](PySimulation& s, const std::string& name,
             const py::array_t<double, py::array::c_style | py::array::forcecast>& values, const py::object& ids) {
            python::set_body_array(s.engine().model(), s.engine().particles(), name, values, ids);
            s.state_changed();
          },
          py::arg("name"), py::arg("values"), py::arg("ids") = py::none());
  m.attr("particle_arrays") = python::particle_array_names();
  m.attr("settable_arrays") = python::settable_array_names();
  m.attr("particle_array_docs") = python::particle_array_docs();
  m.attr("body_arrays") = python::body_array_names();
  m.attr("settable_body_arrays") = python::settable_body_array_names();
  m.attr("body_array_docs") = python::body_array_docs();
}
