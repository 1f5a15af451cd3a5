#pragma once
// Closed triangle surfaces with outward normals for the mass-property and clump-fill tests: a box,
// a regular octahedron and an icosphere (a subdivided icosahedron with its vertices on a sphere);
// an independent quadrature of their mass properties.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "core/rotation.hpp"
#include "core/vec3.hpp"
#include "geometry/triangle_mesh.hpp"

namespace mpdem::test {

// Box [0, a] x [0, b] x [0, c], two triangles per face, normals outward.
inline TriangleMesh solid_box(double a, double b, double c) {
  TriangleMesh m;
  for (int k = 0; k < 8; ++k) m.add_vertex({(k & 1) ? a : 0.0, (k & 2) ? b : 0.0, (k & 4) ? c : 0.0});
  // Faces counter-clockwise seen from outside (vertex k: bit 0 = x, bit 1 = y, bit 2 = z).
  m.add_quad(0, 2, 3, 1);  // z = 0
  m.add_quad(4, 5, 7, 6);  // z = c
  m.add_quad(0, 1, 5, 4);  // y = 0
  m.add_quad(2, 6, 7, 3);  // y = b
  m.add_quad(0, 4, 6, 2);  // x = 0
  m.add_quad(1, 3, 7, 5);  // x = a
  return m;
}

// Regular octahedron |x| + |y| + |z| <= a: volume 4/3 a^3, every moment about the centre a^2/5 of
// the volume (per unit density).
inline TriangleMesh solid_octahedron(double a) {
  TriangleMesh m;
  const int px = m.add_vertex({a, 0, 0}), nx = m.add_vertex({-a, 0, 0}), py = m.add_vertex({0, a, 0}),
            ny = m.add_vertex({0, -a, 0}), pz = m.add_vertex({0, 0, a}), nz = m.add_vertex({0, 0, -a});
  const std::array<int, 2> xs{px, nx}, ys{py, ny}, zs{pz, nz};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) {
        // Octant (sx, sy, sz): counter-clockwise from outside when sx sy sz > 0, else reversed.
        if ((i + j + k) % 2 == 0) m.add_triangle(xs[i], ys[j], zs[k]);
        else m.add_triangle(xs[i], zs[k], ys[j]);
      }
  return m;
}

// Icosphere of radius r about `centre`: the icosahedron (level 0, 20 triangles) with each
// triangle split in four `level` times, new vertices pushed out onto the sphere. 20 * 4^level
// triangles, edges about 1.1 r / 2^level.
inline TriangleMesh icosphere(int level, double r, const Vec3& centre = {}) {
  const double p = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> v = {{-1, p, 0},  {1, p, 0},  {-1, -p, 0}, {1, -p, 0}, {0, -1, p},  {0, 1, p},
                         {0, -1, -p}, {0, 1, -p}, {p, 0, -1},  {p, 0, 1},  {-p, 0, -1}, {-p, 0, 1}};
  for (Vec3& x : v) x = x / norm(x);
  std::vector<std::array<int, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (auto& t : f)  // outward: counter-clockwise seen from outside
    if (dot(cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]), v[t[0]]) < 0.0) std::swap(t[1], t[2]);
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<int, int>, int> mid;
    const auto midpoint = [&](int a, int b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      const auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      const Vec3 m = v[a] + v[b];
      v.push_back(m / norm(m));
      return mid[key] = static_cast<int>(v.size()) - 1;
    };
    std::vector<std::array<int, 3>> g;
    for (const auto& t : f) {
      const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      g.push_back({t[0], ab, ca});
      g.push_back({t[1], bc, ab});
      g.push_back({t[2], ca, bc});
      g.push_back({ab, bc, ca});
    }
    f = std::move(g);
  }
  TriangleMesh m;
  for (const Vec3& x : v) m.add_vertex(centre + x * r);
  for (const auto& t : f) m.add_triangle(t[0], t[1], t[2]);
  return m;
}

// Mass properties per unit density computed independently of geometry/mesh_mass: the signed
// tetrahedra (apex, triangle), each integrated by the 4-point rule exact for quadratics (points
// alpha q_i + beta (the other three), alpha = 0.5854..., beta = 0.1381..., weights V/4), the
// second moments summed about the origin and then moved to the centroid.
struct QuadratureMass {
  double volume = 0.0;  // m^3
  Vec3 centroid;        // m
  Mat3 inertia{};       // m^5, about the centroid
};

inline QuadratureMass quadrature_mass(const TriangleMesh& m, const Vec3& apex) {
  const double alpha = 0.58541019662496845446, beta = 0.13819660112501051518;
  QuadratureMass out;
  Vec3 first;
  Mat3 second{};  // about the origin
  for (std::size_t t = 0; t < m.size(); ++t) {
    const Vec3 q[4] = {apex, m.corner(t, 0), m.corner(t, 1), m.corner(t, 2)};
    const double v = dot(q[1] - q[0], cross(q[2] - q[0], q[3] - q[0])) / 6;
    out.volume += v;
    const Vec3 sum = q[0] + q[1] + q[2] + q[3];
    for (int k = 0; k < 4; ++k) {
      const Vec3 x = q[k] * alpha + (sum - q[k]) * beta;
      first += x * (v / 4);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) second[i][j] += x[i] * x[j] * (v / 4);
    }
  }
  const Vec3 c = first / out.volume;
  out.centroid = c;
  double trace = 0.0;
  for (int i = 0; i < 3; ++i) trace += second[i][i] - out.volume * c[i] * c[i];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out.inertia[i][j] = (i == j ? trace : 0.0) - (second[i][j] - out.volume * c[i] * c[j]);
  return out;
}

}  // namespace mpdem::test
