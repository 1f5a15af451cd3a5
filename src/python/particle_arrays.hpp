#pragma once
// The particles' arrays as numpy arrays, by the names of docs/python.md: copies in id order (the
// engine reorders its particles at neighbour rebuilds), zero-copy views in storage order, and
// setters taking values in id order or for given ids.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <map>
#include <string>
#include <vector>

#include "state/particles.hpp"

namespace mpdem::python {

namespace py = pybind11;

// The arrays' names, the settable ones, and name -> docstring ("(N, 3) N m, total torque ..."):
// all from the particle column table (state/particle_columns.hpp).
std::vector<std::string> particle_array_names();
std::vector<std::string> settable_array_names();
std::map<std::string, std::string> particle_array_docs();
// A copy of array `name` in ascending id order: shape (N,) or (N, 3) ((N, 4) for orientation).
py::array id_ordered(const Particles& p, const std::string& name);
// A read-only view of array `name` in storage order, valid until the next step; `owner` is kept
// alive by the view.
py::array storage_view(Particles& p, const std::string& name, const py::object& owner);
// Sets array `name` from `values` (float64, (N,) or (N, 3)): for the particles `ids`, or for every
// particle in id order when ids is None. Throws ValueError for an unknown id or a wrong shape,
// InputError (a ValueError, key = name) for a value that is not finite, a temperature < 0 K or a
// member sphere of a clump (its state is its body's: python/body_arrays.hpp); nothing is set then.
void set_array(Particles& p, const std::string& name,
               const py::array_t<double, py::array::c_style | py::array::forcecast>& values, const py::object& ids);
// Index of every particle of `ids` (ValueError naming the first unknown one).
std::vector<std::size_t> indices_of(const Particles& p, const py::array_t<std::int64_t>& ids);

}  // namespace mpdem::python
