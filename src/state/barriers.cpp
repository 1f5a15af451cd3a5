#include "state/barriers.hpp"

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
  offset.push_back(law.displacement(0.0));
  velocity.push_back(law.velocity(0.0));
  force.emplace_back();
  moment.emplace_back();
  pressure.push_back(0.0);
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
}

Vec3 Barriers::vertex(std::size_t e, int k) const {
  const Vec3& p = k == 0 ? p0[e] : (k == 1 ? p1[e] : p2[e]);
  return p + offset[e];
}

Vec3 Barriers::centre(std::size_t e) const { return (p0[e] + p1[e] + p2[e]) / 3.0 + offset[e]; }

}  // namespace mpdem
