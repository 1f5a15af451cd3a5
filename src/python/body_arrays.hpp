#pragma once
// The clumps' rigid bodies (state/bodies.hpp) as numpy arrays, by the names of docs/python.md
// ("Bodies"): copies in ascending body id order; the velocity and the angular velocity settable
// between steps (the members then moved with their bodies).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <map>
#include <string>
#include <vector>

#include "model/scene.hpp"
#include "state/particles.hpp"

namespace mpdem::python {

namespace py = pybind11;

// The arrays' names, the settable ones, and name -> docstring ("(B, 3) m/s, ...").
std::vector<std::string> body_array_names();
std::vector<std::string> settable_body_array_names();
std::map<std::string, std::string> body_array_docs();
// A copy of array `name` in ascending body id order: (B,) or (B, 3), (B, 4) for orientations;
// "template" is a list of the templates' names. ValueError for an unknown name.
py::object body_array(const Model& model, const Particles& p, const std::string& name);
// Sets the bodies' `name` (velocity or angular_velocity) from `values` ((B, 3) float64): for the
// bodies `ids`, or for every body in id order when ids is None; then sets the members' velocities
// from their bodies' (model/body_members.hpp move_members). The caller re-evaluates the rates
// (Simulation::state_changed). ValueError for an unknown id, a wrong shape or an array that cannot
// be set, InputError (a ValueError, key = name) for a value that is not finite; nothing is set then.
void set_body_array(const Model& model, Particles& p, const std::string& name,
                    const py::array_t<double, py::array::c_style | py::array::forcecast>& values,
                    const py::object& ids);

}  // namespace mpdem::python
