// Mass properties of a closed triangle surface by signed tetrahedra (geometry/mesh_mass.hpp).
#include "geometry/mesh_mass.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mpdem {

MeshMassProperties mesh_mass_properties(const TriangleMesh& mesh) {
  if (mesh.size() == 0) throw std::invalid_argument("the mesh has no triangles");
  Vec3 lo = mesh.vertices[mesh.triangles[0][0]], hi = lo;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = mesh.vertices[t[k]];
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  const Vec3 o = (lo + hi) * 0.5;  // m, reference point

  double v6 = 0.0;  // m^3, 6 x volume
  Vec3 m24;         // m^4, 24 x first moment about o
  Mat3 c120{};      // m^5, 120 x covariance about o
  for (std::size_t t = 0; t < mesh.size(); ++t) {
    const Vec3 u = mesh.corner(t, 0) - o, v = mesh.corner(t, 1) - o, w = mesh.corner(t, 2) - o;
    const double d = dot(u, cross(v, w));
    const Vec3 s = u + v + w;
    v6 += d;
    m24 += s * d;
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j) c120[i][j] += d * (u[i] * u[j] + v[i] * v[j] + w[i] * w[j] + s[i] * s[j]);
  }
  MeshMassProperties out;
  double sign = 1.0;
  if (v6 < 0.0) {
    sign = -1.0;
    out.inward = true;
  }
  out.volume = sign * v6 / 6.0;
  if (!(out.volume > 0.0) || !std::isfinite(out.volume)) throw std::invalid_argument("the mesh encloses no volume");
  const Vec3 c = m24 * (sign / 24.0) / out.volume;  // centroid relative to o
  out.centroid = o + c;
  Mat3 cov{};  // m^5, covariance about the centroid
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) cov[i][j] = cov[j][i] = sign * c120[i][j] / 120.0 - out.volume * c[i] * c[j];
  const double trace = cov[0][0] + cov[1][1] + cov[2][2];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out.inertia[i][j] = (i == j ? trace : 0.0) - cov[i][j];
  return out;
}

}  // namespace mpdem
