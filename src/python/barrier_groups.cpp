#include "python/barrier_groups.hpp"

#include <fmt/core.h>

#include <cmath>

#include "core/input_error.hpp"

namespace mpdem::python {

namespace {
int group_index(const Barriers& b, const std::string& group) {
  for (std::size_t g = 0; g < b.group_names.size(); ++g)
    if (b.group_names[g] == group) return static_cast<int>(g);
  std::string known;
  for (const std::string& n : b.group_names) known += (known.empty() ? "" : ", ") + n;
  throw py::value_error("no barrier group '" + group + "' (groups: " + (known.empty() ? "none" : known) + ")");
}

py::array_t<double> vec(const Vec3& v) {
  py::array_t<double> a(3);
  a.mutable_data()[0] = v.x;
  a.mutable_data()[1] = v.y;
  a.mutable_data()[2] = v.z;
  return a;
}
}  // namespace

py::list group_names(const Barriers& b) {
  py::list out;
  for (const std::string& n : b.group_names) out.append(n);
  return out;
}

py::dict group_load(const Barriers& b, const std::string& group) {
  const int g = group_index(b, group);
  Vec3 f{}, m{};
  double torque = 0.0, power = 0.0, area = 0.0;
  for (std::size_t e = 0; e < b.size(); ++e) {
    if (b.group[e] != g) continue;
    f += b.force[e];
    m += b.moment[e] + cross(b.centre(e), b.force[e]);  // about the origin
    torque += b.axis_torque(e);
    power += b.drive_power(e);
    area += b.area[e];
  }
  py::dict d;
  d["force"] = vec(f);
  d["moment"] = vec(m);
  d["axis_torque"] = torque;
  d["power"] = power;
  d["area"] = area;
  return d;
}

py::tuple group_motion(const Barriers& b, const std::string& group) {
  const int g = group_index(b, group);
  for (std::size_t e = 0; e < b.size(); ++e)
    if (b.group[e] == g) return py::make_tuple(vec(b.offset[e]), vec(b.velocity[e]));
  return py::make_tuple(vec({}), vec({}));
}

void set_group_velocity(Barriers& b, const std::string& group, const Vec3& v, double t) {
  const int g = group_index(b, group);
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
    throw InputError("", 0, "velocity",
                     fmt::format("components must be finite, got [{}, {}, {}] (group '{}')", v.x, v.y, v.z, group));
  for (std::size_t e = 0; e < b.size(); ++e) {
    if (b.group[e] != g) continue;
    const MotionLaw& law = b.motion[e];
    if (law.rotation || (norm2(law.A) != 0.0 && law.w1 != 0.0) || (norm2(law.B) != 0.0 && law.w2 != 0.0))
      throw py::value_error("barrier group '" + group +
                            "' has a periodic or rotating motion law: only a translating group's velocity can be set");
  }
  for (std::size_t e = 0; e < b.size(); ++e) {
    if (b.group[e] != g) continue;
    MotionLaw& law = b.motion[e];
    // u(s) = a s + B cos(0 s): a = v, and the constant B keeps u continuous at the law's time s(t).
    const Vec3 u = law.displacement(t);
    const double s = law.law_time(t);
    law.a = v;
    law.A = {};
    law.w1 = 0.0;
    law.B = u - v * s;
    law.w2 = 0.0;
  }
  b.move_to(t);
}

}  // namespace mpdem::python
