// Chute barrier mesh: incline, circular-arc transition, horizontal run-out (thesis case study 1,
// the Hutter apparatus), with optional side walls.
#include <cmath>
#include <stdexcept>
#include <vector>

#include "tools/mesh_builder.hpp"

namespace mpdem {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

TriangleMesh make_chute(const ChuteSpec& s) {
  if (!(s.incline_length > 0 && s.angle_deg > 0 && s.angle_deg < 90 && s.transition_radius >= 0 &&
        s.runout_length >= 0 && s.width > 0 && s.wall_height >= 0 && s.arc_segments >= 1))
    throw std::invalid_argument(
        "chute: expected incline length, width > 0, 0 < angle < 90 deg, radius, run-out, wall height >= 0 "
        "and arc segments >= 1");
  const double th = s.angle_deg * kPi / 180.0;
  const double R = s.transition_radius;
  // Profile in the x-z plane from the top of the incline to the end of the run-out. The arc's
  // centre is (0, R): it touches the run-out at the origin and the incline at angle th.
  std::vector<Vec3> profile;
  const Vec3 arc_start{-R * std::sin(th), 0.0, R * (1.0 - std::cos(th))};
  profile.push_back(arc_start + Vec3{-std::cos(th), 0.0, std::sin(th)} * s.incline_length);
  if (R > 0) {
    for (int k = 0; k < s.arc_segments; ++k) {
      const double phi = -0.5 * kPi - th + th * k / s.arc_segments;
      profile.push_back({R * std::cos(phi), 0.0, R + R * std::sin(phi)});
    }
  }
  profile.push_back({0.0, 0.0, 0.0});
  if (s.runout_length > 0) profile.push_back({s.runout_length, 0.0, 0.0});

  TriangleMesh m;
  const int np = static_cast<int>(profile.size());
  const double hw = 0.5 * s.width;
  std::vector<int> left(np), right(np);  // profile at y = -w/2 and y = +w/2
  for (int i = 0; i < np; ++i) {
    left[i] = m.add_vertex(profile[i] + Vec3{0, -hw, 0});
    right[i] = m.add_vertex(profile[i] + Vec3{0, hw, 0});
  }
  for (int i = 0; i + 1 < np; ++i) m.add_quad(left[i], left[i + 1], right[i + 1], right[i]);  // floor, normals up
  if (s.wall_height > 0) {
    const Vec3 up{0, 0, s.wall_height};
    std::vector<int> left_top(np), right_top(np);
    for (int i = 0; i < np; ++i) {
      left_top[i] = m.add_vertex(m.vertices[left[i]] + up);
      right_top[i] = m.add_vertex(m.vertices[right[i]] + up);
    }
    for (int i = 0; i + 1 < np; ++i) {
      m.add_quad(left[i], left_top[i], left_top[i + 1], left[i + 1]);      // normal +y (inward)
      m.add_quad(right[i], right[i + 1], right_top[i + 1], right_top[i]);  // normal -y (inward)
    }
  }
  return m;
}

}  // namespace mpdem
