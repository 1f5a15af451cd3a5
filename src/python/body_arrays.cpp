#include "python/body_arrays.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string_view>
#include <type_traits>

#include "core/input_error.hpp"
#include "model/body_members.hpp"
#include "python/numpy_layout.hpp"

namespace mpdem::python {

namespace {

struct BodyArray {
  const char* name;   // sim.bodies.<name>
  const char* unit;   // SI unit, "-" for none
  const char* about;  // what it is, a few words (Python docstrings)
  bool settable;      // Python may assign it between steps
};

// The arrays in the order of mpdem._core.body_arrays.
constexpr BodyArray kBodyArrays[] = {
    {"id", "-", "the bodies' ids (the body CSV's), ascending", false},
    {"template", "-", "the name of each body's clump template", false},
    {"material", "-", "index into sim.materials", false},
    {"position", "m", "centre of mass", false},
    {"orientation", "-",
     "unit quaternion (w, x, y, z): the template's frame as written -> world (the body CSV's q0..q3)", false},
    {"principal_orientation", "-", "unit quaternion (w, x, y, z): the principal axes' frame -> world", false},
    {"velocity", "m/s", "velocity of the centre of mass", true},
    {"angular_velocity", "rad/s", "angular velocity (world frame)", true},
    {"mass", "kg", "mass", false},
    {"inertia", "kg m^2", "principal moments I1, I2, I3 (about the principal axes)", false},
    {"force", "N", "total force of the last evaluation: the members' contacts and the fields", false},
    {"torque", "N m", "total torque about the centre of mass of the last evaluation", false},
    {"temperature", "K", "temperature (one per body)", false},
    {"heat", "W", "heat flow into the body of the last evaluation", false},
    {"charge", "C", "charge", false},
    {"fixed", "-", "1: prescribed motion (velocity and angular velocity kept)", false},
};

// f(get) with get(b) the value of array `name` for body index b; false for an unknown name (and
// for "template", whose names are not numbers).
template <class F>
bool with_values(const Model& model, const Bodies& B, const std::string& name, F&& f) {
  const auto field = [&f](const auto& a) {
    f([&a](std::size_t b) { return a[b]; });
    return true;
  };
  if (name == "id") return field(B.id);
  if (name == "material") return field(B.material);
  if (name == "position") return field(B.x);
  if (name == "principal_orientation") return field(B.q);
  if (name == "velocity") return field(B.v);
  if (name == "angular_velocity") return field(B.w);
  if (name == "mass") return field(B.mass);
  if (name == "inertia") return field(B.inertia);
  if (name == "force") return field(B.force);
  if (name == "torque") return field(B.torque);
  if (name == "temperature") return field(B.T);
  if (name == "heat") return field(B.heat);
  if (name == "charge") return field(B.charge);
  if (name == "fixed") return field(B.fixed);
  if (name == "orientation") {
    // The body CSV's convention: the engine's q is q_csv to_input (model/body_members.hpp add_body).
    f([&](std::size_t b) {
      const Quat& t = model.clumps[static_cast<std::size_t>(B.clump[b])].shape.to_input;
      return quat_multiply(B.q[b], Quat{t.w, -t.x, -t.y, -t.z});
    });
    return true;
  }
  return false;
}

[[noreturn]] void unknown(const std::string& name) {
  std::string known;
  for (const std::string& n : body_array_names()) known += (known.empty() ? "" : ", ") + n;
  throw py::value_error("no body array '" + name + "' (known: " + known + ")");
}

// Body indices in ascending id order (bodies keep their order, which is the scene's).
std::vector<std::size_t> id_order(const Bodies& B) {
  std::vector<std::size_t> order(B.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return B.id[a] < B.id[b]; });
  return order;
}

std::vector<std::size_t> indices_of(const Bodies& B, const py::array_t<std::int64_t>& ids) {
  const auto v = ids.unchecked<1>();
  std::vector<std::size_t> out(static_cast<std::size_t>(v.shape(0)));
  for (py::ssize_t k = 0; k < v.shape(0); ++k) {
    const std::ptrdiff_t b = B.find(v(k));
    if (b < 0) throw py::value_error("no body with id " + std::to_string(v(k)));
    out[static_cast<std::size_t>(k)] = static_cast<std::size_t>(b);
  }
  return out;
}

}  // namespace

std::vector<std::string> body_array_names() {
  std::vector<std::string> out;
  for (const BodyArray& a : kBodyArrays) out.emplace_back(a.name);
  return out;
}

std::vector<std::string> settable_body_array_names() {
  std::vector<std::string> out;
  for (const BodyArray& a : kBodyArrays)
    if (a.settable) out.emplace_back(a.name);
  return out;
}

std::map<std::string, std::string> body_array_docs() {
  static const Model no_model;
  static const Bodies no_bodies;
  std::map<std::string, std::string> out;
  for (const BodyArray& a : kBodyArrays) {
    std::string shape = "(B,) str";  // "template"
    with_values(no_model, no_bodies, a.name, [&](const auto& get) {
      using T = std::decay_t<decltype(get(0))>;
      using S = typename Layout<T>::Scalar;
      shape = Layout<T>::width == 1 ? "(B,)" : fmt::format("(B, {})", Layout<T>::width);
      if (!std::is_same_v<S, double>) shape += " " + std::string(py::str(py::dtype::of<S>()));
    });
    if (std::string_view(a.unit) != "-") shape += std::string(" ") + a.unit;
    out[a.name] = shape + ", " + a.about;
  }
  return out;
}

py::object body_array(const Model& model, const Particles& p, const std::string& name) {
  const Bodies& B = p.bodies;
  const std::vector<std::size_t> order = id_order(B);
  if (name == "template") {
    py::list names;
    for (const std::size_t b : order) names.append(model.clumps[static_cast<std::size_t>(B.clump[b])].name);
    return names;
  }
  py::object out;
  if (!with_values(model, B, name, [&](const auto& get) {
        using T = std::decay_t<decltype(get(0))>;
        py::array_t<typename Layout<T>::Scalar> copy(shape_of<T>(order.size()));
        auto* dst = reinterpret_cast<T*>(copy.mutable_data());
        for (std::size_t k = 0; k < order.size(); ++k) dst[k] = get(order[k]);
        out = std::move(copy);
      }))
    unknown(name);
  return out;
}

void set_body_array(const Model& model, Particles& p, const std::string& name,
                    const py::array_t<double, py::array::c_style | py::array::forcecast>& values,
                    const py::object& ids) {
  Bodies& B = p.bodies;
  std::vector<Vec3>* a = name == "velocity" ? &B.v : name == "angular_velocity" ? &B.w : nullptr;
  if (a == nullptr) {
    std::string known;
    for (const std::string& n : settable_body_array_names()) known += (known.empty() ? "" : ", ") + n;
    throw py::value_error("body array '" + name + "' cannot be set (settable: " + known + ")");
  }
  const std::vector<std::size_t> target = ids.is_none()
                                              ? id_order(B)
                                              : indices_of(
                                                    B, py::array_t<std::int64_t, py::array::forcecast>::ensure(ids));
  const auto n = static_cast<py::ssize_t>(target.size());
  if (values.ndim() != 2 || values.shape(0) != n || values.shape(1) != 3)
    throw py::value_error("'" + name + "' needs " + std::to_string(n) + " rows of 3 values, got an array of shape (" +
                          std::to_string(values.shape(0)) +
                          (values.ndim() > 1 ? ", " + std::to_string(values.shape(1)) : std::string()) + ")");
  const double* v = values.data();
  for (py::ssize_t k = 0; k < 3 * n; ++k)
    if (!std::isfinite(v[k]))
      throw InputError("", 0, name,
                       fmt::format("values must be finite (row {}, body id {}: {})", k / 3,
                                   B.id[target[static_cast<std::size_t>(k / 3)]], v[k]));
  for (std::size_t k = 0; k < target.size(); ++k) (*a)[target[k]] = {v[3 * k], v[3 * k + 1], v[3 * k + 2]};
  move_members(model.clumps, p);
}

}  // namespace mpdem::python
