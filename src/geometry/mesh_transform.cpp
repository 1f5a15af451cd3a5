#include "geometry/mesh_transform.hpp"

#include <cmath>
#include <numbers>

namespace mpdem {

Vec3 rotate_xyz_deg(const Vec3& p, const Vec3& deg) {
  const double d2r = std::numbers::pi / 180.0;
  const double cx = std::cos(deg.x * d2r), sx = std::sin(deg.x * d2r);
  const double cy = std::cos(deg.y * d2r), sy = std::sin(deg.y * d2r);
  const double cz = std::cos(deg.z * d2r), sz = std::sin(deg.z * d2r);
  const Vec3 a{p.x, cx * p.y - sx * p.z, sx * p.y + cx * p.z};   // about x
  const Vec3 b{cy * a.x + sy * a.z, a.y, -sy * a.x + cy * a.z};  // about y
  return {cz * b.x - sz * b.y, sz * b.x + cz * b.y, b.z};        // about z
}

void transform_mesh(TriangleMesh& mesh, double scale, const Vec3& rotate_deg, const Vec3& translate) {
  const bool rotate = !(rotate_deg == Vec3{});
  for (Vec3& p : mesh.vertices) p = (rotate ? rotate_xyz_deg(p * scale, rotate_deg) : p * scale) + translate;
}

}  // namespace mpdem
