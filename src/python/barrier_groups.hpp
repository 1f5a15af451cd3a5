#pragma once
// Barrier groups from Python (mpdem.Simulation.barriers): the loads of the last evaluation per
// group, the group's translation, and a new constant velocity set between steps (a servo wall).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

#include "state/barriers.hpp"

namespace mpdem::python {

namespace py = pybind11;

py::list group_names(const Barriers& b);
// {"force": (3,) N, "moment": (3,) N m about the origin, "axis_torque": N m, "power": W,
//  "area": m^2}: the sums over the group's active elements, as barrier_groups.csv writes them.
py::dict group_load(const Barriers& b, const std::string& group);
// (3,) m and m/s: the translation u(t) and velocity u'(t) of the group's first element.
py::tuple group_motion(const Barriers& b, const std::string& group);
// From time t on, the group translates at the constant velocity v (m/s), its position continuous
// at t. A group whose law has a sine, cosine or rotation term is refused (ValueError), as is a
// component that is not finite (InputError, key "velocity").
void set_group_velocity(Barriers& b, const std::string& group, const Vec3& v, double t);

}  // namespace mpdem::python
