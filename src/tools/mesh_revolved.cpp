// Barrier meshes of revolution about the z axis: cylinder and funnel (hopper).
#include <cmath>
#include <stdexcept>
#include <vector>

#include "tools/mesh_builder.hpp"

namespace mpdem {

namespace {

constexpr double kPi = 3.14159265358979323846;

// n vertices on the circle of radius r at height z; returns the index of the first.
int add_ring(TriangleMesh& m, double r, double z, int n) {
  const int first = static_cast<int>(m.vertices.size());
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * kPi * k / n;
    m.add_vertex({r * std::cos(a), r * std::sin(a), z});
  }
  return first;
}

// Band of quads between two rings, wound so the normals point away from the axis.
void add_band(TriangleMesh& m, int lower, int upper, int n) {
  for (int k = 0; k < n; ++k) {
    const int k1 = (k + 1) % n;
    m.add_quad(lower + k, lower + k1, upper + k1, upper + k);
  }
}

}  // namespace

TriangleMesh make_cylinder(double radius, double height, int segments, bool closed) {
  if (!(radius > 0 && height > 0) || segments < 3)
    throw std::invalid_argument("cylinder: expected radius, height > 0 and segments >= 3");
  TriangleMesh m;
  const int n = segments;
  const int bottom = add_ring(m, radius, 0.0, n), top = add_ring(m, radius, height, n);
  add_band(m, bottom, top, n);  // outward
  if (closed) {
    const int cb = m.add_vertex({0, 0, 0}), ct = m.add_vertex({0, 0, height});
    for (int k = 0; k < n; ++k) {
      const int k1 = (k + 1) % n;
      m.add_triangle(cb, bottom + k1, bottom + k);  // -z, outward
      m.add_triangle(ct, top + k, top + k1);        // +z, outward
    }
  }
  m.flip();  // particles live inside
  return m;
}

TriangleMesh make_funnel(double top_radius, double outlet_radius, double height, double wall_height, int segments) {
  if (!(top_radius > 0 && outlet_radius > 0 && height > 0 && wall_height >= 0) || segments < 3)
    throw std::invalid_argument("funnel: expected radii, height > 0, wall height >= 0 and segments >= 3");
  TriangleMesh m;
  const int n = segments;
  const int outlet = add_ring(m, outlet_radius, 0.0, n), rim = add_ring(m, top_radius, height, n);
  add_band(m, outlet, rim, n);
  if (wall_height > 0) add_band(m, rim, add_ring(m, top_radius, height + wall_height, n), n);
  m.flip();  // normals towards the axis: particles inside
  return m;
}

}  // namespace mpdem
