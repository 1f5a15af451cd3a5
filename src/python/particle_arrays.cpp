#include "python/particle_arrays.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <string_view>
#include <type_traits>
#include <stdexcept>
#include <unordered_map>

#include "core/input_error.hpp"
#include "python/numpy_layout.hpp"
#include "state/particle_columns.hpp"

namespace mpdem::python {

namespace {

// The storage-order index of each particle in ascending id order.
std::vector<std::size_t> id_order(const Particles& p) {
  std::vector<std::size_t> order(p.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p.id[a] < p.id[b]; });
  return order;
}

// f(array) with the engine's array of a Python name (state/particle_columns.hpp); false for an
// unknown name.
template <class F>
bool with_array(Particles& p, const std::string& name, F&& f) {
  bool found = false;
  for_each_particle_column([&](const auto& c) {
    if (!found && name == c.name) {
      f(p.*c.array);
      found = true;
    }
  });
  return found;
}

[[noreturn]] void unknown(const std::string& name) {
  std::string known;
  for (const std::string& n : particle_array_names()) known += (known.empty() ? "" : ", ") + n;
  throw py::value_error("no particle array '" + name + "' (known: " + known + ")");
}

// Every value finite, and a temperature >= 0 (the particle CSV's range), before any is set: a
// NaN would otherwise surface as a diverged state one step later, far from the call.
void check_values(const Particles& p, const std::string& name,
                  const py::array_t<double, py::array::c_style | py::array::forcecast>& values,
                  const std::vector<std::size_t>& target) {
  const std::size_t width = values.ndim() == 1 ? 1 : static_cast<std::size_t>(values.shape(1));
  const double* v = values.data();
  for (std::size_t k = 0; k < target.size() * width; ++k) {
    const bool finite = std::isfinite(v[k]);
    if (finite && !(name == "temperature" && v[k] < 0.0)) continue;
    const std::size_t row = k / width;
    throw InputError("", 0, name,
                     fmt::format("{} (row {}, particle id {}: {})",
                                 finite ? "temperatures must be >= 0 K" : "values must be finite", row,
                                 p.id[target[row]], v[k]));
  }
}

}  // namespace

std::vector<std::string> particle_array_names() {
  std::vector<std::string> out;
  for_each_particle_column([&out](const auto& c) { out.emplace_back(c.name); });
  return out;
}

std::vector<std::string> settable_array_names() {
  std::vector<std::string> out;
  for_each_particle_column([&out](const auto& c) {
    if (c.settable) out.emplace_back(c.name);
  });
  return out;
}

std::map<std::string, std::string> particle_array_docs() {
  std::map<std::string, std::string> out;
  for_each_particle_column([&out](const auto& c) {
    using T = typename std::decay_t<decltype(c)>::Value;
    using S = typename Layout<T>::Scalar;
    const std::string shape = c.components == 1 ? "(N,)" : fmt::format("(N, {})", c.components);
    std::string dtype = py::str(py::dtype::of<S>());
    std::string doc = shape + (std::is_same_v<S, double> ? "" : " " + dtype);
    if (std::string_view(c.unit) != "-") doc += std::string(" ") + c.unit;
    out[c.name] = doc + ", " + c.about;
  });
  return out;
}

py::array id_ordered(const Particles& p, const std::string& name) {
  const std::vector<std::size_t> order = id_order(p);
  py::array out;
  auto& mut = const_cast<Particles&>(p);  // with_array only reads here
  if (!with_array(mut, name, [&](auto& a) {
        using T = typename std::decay_t<decltype(a)>::value_type;
        using S = typename Layout<T>::Scalar;
        py::array_t<S> copy(shape_of<T>(order.size()));
        auto* dst = reinterpret_cast<T*>(copy.mutable_data());
        for (std::size_t k = 0; k < order.size(); ++k) dst[k] = a[order[k]];
        out = copy;
      }))
    unknown(name);
  return out;
}

py::array storage_view(Particles& p, const std::string& name, const py::object& owner) {
  py::array out;
  if (!with_array(p, name, [&](auto& a) {
        using T = typename std::decay_t<decltype(a)>::value_type;
        using S = typename Layout<T>::Scalar;
        std::vector<py::ssize_t> strides{static_cast<py::ssize_t>(sizeof(T))};
        if (Layout<T>::width > 1) strides.push_back(static_cast<py::ssize_t>(sizeof(S)));
        out = py::array_t<S>(shape_of<T>(p.size()), strides, reinterpret_cast<const S*>(a.data()), owner);
        py::detail::array_proxy(out.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
      }))
    unknown(name);
  return out;
}

std::vector<std::size_t> indices_of(const Particles& p, const py::array_t<std::int64_t>& ids) {
  std::unordered_map<std::int64_t, std::size_t> index;
  index.reserve(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) index.emplace(p.id[i], i);
  const auto v = ids.unchecked<1>();
  std::vector<std::size_t> out(static_cast<std::size_t>(v.shape(0)));
  for (py::ssize_t k = 0; k < v.shape(0); ++k) {
    const auto it = index.find(v(k));
    if (it == index.end()) throw py::value_error("no particle with id " + std::to_string(v(k)));
    out[static_cast<std::size_t>(k)] = it->second;
  }
  return out;
}

void set_array(Particles& p, const std::string& name,
               const py::array_t<double, py::array::c_style | py::array::forcecast>& values, const py::object& ids) {
  const auto settable = settable_array_names();
  if (std::find(settable.begin(), settable.end(), name) == settable.end()) {
    std::string known;
    for (const std::string& n : settable) known += (known.empty() ? "" : ", ") + n;
    throw py::value_error("particle array '" + name + "' cannot be set (settable: " + known + ")");
  }
  const std::vector<std::size_t> target = ids.is_none()
                                              ? id_order(p)
                                              : indices_of(
                                                    p, py::array_t<std::int64_t, py::array::forcecast>::ensure(ids));
  // A member sphere of a clump moves with its body (model/body_members.hpp): a state of its own
  // would be overwritten at the next step, and the forces evaluated at it would be wrong.
  for (std::size_t k = 0; k < target.size(); ++k)
    if (p.body[target[k]] != kNoBody)
      throw InputError("", 0, name,
                       fmt::format("particle id {} (row {}) is a member of clump body {} and moves with it: set "
                                   "sim.bodies.velocity or angular_velocity, or give the ids of free spheres",
                                   p.id[target[k]], k, p.body[target[k]]));
  with_array(p, name, [&](auto& a) {
    using T = typename std::decay_t<decltype(a)>::value_type;
    if constexpr (std::is_same_v<T, Vec3> || std::is_same_v<T, double>) {
      const py::ssize_t width = Layout<T>::width;
      const bool ok = width == 1 ? values.ndim() == 1 && values.shape(0) == static_cast<py::ssize_t>(target.size())
                                 : values.ndim() == 2 && values.shape(0) == static_cast<py::ssize_t>(target.size()) &&
                                       values.shape(1) == width;
      if (!ok)
        throw py::value_error("'" + name + "' needs " + std::to_string(target.size()) +
                              (width == 1 ? " values" : " rows of 3 values") + ", got an array of shape (" +
                              std::to_string(values.shape(0)) +
                              (values.ndim() > 1 ? ", " + std::to_string(values.shape(1)) : std::string()) + ")");
      check_values(p, name, values, target);
      const auto* src = reinterpret_cast<const T*>(values.data());
      for (std::size_t k = 0; k < target.size(); ++k) a[target[k]] = src[k];
    }
  });
}

}  // namespace mpdem::python
