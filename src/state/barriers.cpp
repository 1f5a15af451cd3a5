#include "state/barriers.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/triangle_check.hpp"

namespace mpdem {

bool Barriers::add(std::int64_t bid, const Vec3& a, const Vec3& b, const Vec3& c, int grp, double E, double nu,
                   const MotionLaw& law, double t_b, double temp) {
  const Vec3 n = cross(b - a, c - a);
  const double twice_area = norm(n);
  // Degenerate (zero-area) triangles have no normal; the caller reports them.
  if (!(twice_area > kMinTwiceArea)) return false;
  id.push_back(bid);
  p0.push_back(a);
  p1.push_back(b);
  p2.push_back(c);
  normal.push_back(n / twice_area);
  area.push_back(0.5 * twice_area);
  group.push_back(grp);
  material.push_back(-1);
  young.push_back(E);
  poisson.push_back(nu);
  thickness.push_back(t_b);
  temperature.push_back(temp);
  motion.push_back(law);
  std::int32_t l = -1;
  if (law.rotation) {
    // Elements of one source share a law: the last one is the likely match.
    const auto it = std::find(rotations.rbegin(), rotations.rend(), *law.rotation);
    if (it != rotations.rend()) {
      l = static_cast<std::int32_t>(rotations.rend() - it - 1);
    } else {
      l = static_cast<std::int32_t>(rotations.size());
      rotations.push_back(*law.rotation);
      angle.push_back(0.0);
      turn.emplace_back();
      spin.emplace_back();
    }
  }
  rotation_of.push_back(l);
  active.push_back(!law.timed() || law.active_at(time));
  timed_elements += law.timed();
  offset.push_back(law.displacement(time));
  velocity.push_back(law.velocity(time));
  force.emplace_back();
  moment.emplace_back();
  pressure.push_back(0.0);
  if (l >= 0) turn_to(time);
  return true;
}

int Barriers::group_index(const std::string& name) {
  for (std::size_t g = 0; g < group_names.size(); ++g)
    if (group_names[g] == name) return static_cast<int>(g);
  group_names.push_back(name);
  return static_cast<int>(group_names.size() - 1);
}

void Barriers::move_to(double t) {
  for (std::size_t e = 0; e < size(); ++e) {
    offset[e] = motion[e].displacement(t);
    velocity[e] = motion[e].velocity(t);
  }
  if (timed())
    for (std::size_t e = 0; e < size(); ++e) active[e] = !motion[e].timed() || motion[e].active_at(t);
  turn_to(t);
}

void Barriers::turn_to(double t) {
  time = t;
  for (std::size_t l = 0; l < rotations.size(); ++l) {
    const RotationLaw& r = rotations[l];
    angle[l] = r.angle(t);
    turn[l] = axis_angle_matrix(r.axis, angle[l]);
    spin[l] = r.axis * r.rate(t);
  }
}

Vec3 Barriers::vertex(std::size_t e, int k) const { return place(e, k == 0 ? p0[e] : (k == 1 ? p1[e] : p2[e])); }

Vec3 Barriers::centre(std::size_t e) const {
  if (rotation_of[e] < 0) return (p0[e] + p1[e] + p2[e]) / 3.0 + offset[e];
  return place(e, (p0[e] + p1[e] + p2[e]) / 3.0);
}

Vec3 Barriers::current_normal(std::size_t e) const {
  const std::int32_t l = rotation_of[e];
  return l < 0 ? normal[e] : mat_apply(turn[static_cast<std::size_t>(l)], normal[e]);
}

Vec3 Barriers::pivot(std::size_t e) const {
  const std::int32_t l = rotation_of[e];
  return l < 0 ? offset[e] : rotations[static_cast<std::size_t>(l)].origin + offset[e];
}

double Barriers::max_point_speed() const {
  double fastest = 0.0;                                        // m/s
  const std::uint8_t* on = timed() ? active.data() : nullptr;  // null: all active
  for (std::size_t e = 0; e < size(); ++e) {
    if (on && !on[e]) continue;
    double v = norm(velocity[e]);
    if (const std::int32_t l = rotation_of[e]; l >= 0) {
      const RotationLaw& r = rotations[static_cast<std::size_t>(l)];
      double arm2 = 0.0;  // m^2, largest squared distance of a vertex from the axis (rotation invariant)
      for (const Vec3& p : {p0[e], p1[e], p2[e]}) {
        const Vec3 d = p - r.origin;
        arm2 = std::max(arm2, norm2(d - dot(d, r.axis) * r.axis));
      }
      v += norm(spin[static_cast<std::size_t>(l)]) * std::sqrt(arm2);
    }
    fastest = std::max(fastest, v);
  }
  return fastest;
}

double Barriers::axis_torque(std::size_t e) const {
  const std::int32_t l = rotation_of[e];
  if (l < 0) return 0.0;
  const Vec3 about_pivot = moment[e] + cross(centre(e) - pivot(e), force[e]);
  return dot(rotations[static_cast<std::size_t>(l)].axis, about_pivot);
}

double Barriers::drive_power(std::size_t e) const {
  double p = dot(force[e], velocity[e]);  // W, of the translation
  if (const std::int32_t l = rotation_of[e]; l >= 0)
    p += dot(spin[static_cast<std::size_t>(l)], moment[e] + cross(centre(e) - pivot(e), force[e]));
  return -p;
}

}  // namespace mpdem
