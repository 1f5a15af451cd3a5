#pragma once
// The parallel bonds from Python (mpdem.Simulation.bonds, docs/python.md "Bonds"): their state as
// numpy arrays, the breaks since the last look, and bonds added between steps.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>

#include "sim/simulation.hpp"

namespace mpdem::python {

namespace py = pybind11;

// {id_i, id_j: (n,) int64; intact: (n,) bool; normal_force (n,) N; shear_force (n, 3) N;
//  twisting_moment (n,) N m; bending_moment (n, 3) N m; sigma, tau (n,) Pa; length (n,) m}, in the
// bonds' (id) order; None without [bonds].
py::object bond_arrays(Simulation& sim);
// The breaks since the last call: {time (k,) s, id_i, id_j (k,) int64, mode (k,) str "tension" |
// "shear", sigma, tau (k,) Pa at the break}, in the order of bonds_broken.csv; None without [bonds].
py::object new_bond_breaks(Simulation& sim);

}  // namespace mpdem::python
