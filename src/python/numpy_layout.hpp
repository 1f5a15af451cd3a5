#pragma once
// How one engine array entry lies in a numpy array: its scalar type and its components per row
// (1: shape (N,), 3: vectors and image counters (N, 3), 4: quaternions (N, 4)).
#include <pybind11/numpy.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/rotation.hpp"
#include "core/vec3.hpp"

namespace mpdem::python {

namespace py = pybind11;

template <class T>
struct Layout {
  using Scalar = T;
  static constexpr py::ssize_t width = 1;
};
template <>
struct Layout<Vec3> {
  using Scalar = double;
  static constexpr py::ssize_t width = 3;
};
template <>
struct Layout<Quat> {
  using Scalar = double;
  static constexpr py::ssize_t width = 4;
};
template <>
struct Layout<std::array<std::int32_t, 3>> {
  using Scalar = std::int32_t;
  static constexpr py::ssize_t width = 3;
};

// The numpy shape of n entries of T: (n,) or (n, width).
template <class T>
std::vector<py::ssize_t> shape_of(std::size_t n) {
  if (Layout<T>::width == 1) return {static_cast<py::ssize_t>(n)};
  return {static_cast<py::ssize_t>(n), Layout<T>::width};
}

}  // namespace mpdem::python
