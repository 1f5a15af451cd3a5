// Flat and box-shaped barrier meshes: rectangle, box, plates with holes.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "tools/mesh_builder.hpp"

namespace mpdem {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

TriangleMesh make_rectangle(double lx, double ly, int nx, int ny) {
  if (!(lx > 0 && ly > 0) || nx < 1 || ny < 1)
    throw std::invalid_argument("rectangle: expected sizes > 0 and nx, ny >= 1");
  TriangleMesh m;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.add_vertex({-0.5 * lx + lx * i / nx, -0.5 * ly + ly * j / ny, 0.0});
  const auto v = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) m.add_quad(v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1));  // +z
  return m;
}

TriangleMesh make_box(double lx, double ly, double lz, bool closed) {
  if (!(lx > 0 && ly > 0 && lz > 0)) throw std::invalid_argument("box: expected sizes > 0");
  TriangleMesh m;
  // Corner (i, j, k) at (+-lx/2, +-ly/2, 0 or lz); index i + 2 j + 4 k.
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) m.add_vertex({(i - 0.5) * lx, (j - 0.5) * ly, k * lz});
  const auto c = [](int i, int j, int k) { return i + 2 * j + 4 * k; };
  // Faces wound outward, flipped to inward at the end.
  m.add_quad(c(0, 0, 0), c(0, 1, 0), c(1, 1, 0), c(1, 0, 0));              // floor, -z
  m.add_quad(c(0, 0, 0), c(1, 0, 0), c(1, 0, 1), c(0, 0, 1));              // y = -ly/2, -y
  m.add_quad(c(0, 1, 0), c(0, 1, 1), c(1, 1, 1), c(1, 1, 0));              // y = +ly/2, +y
  m.add_quad(c(0, 0, 0), c(0, 0, 1), c(0, 1, 1), c(0, 1, 0));              // x = -lx/2, -x
  m.add_quad(c(1, 0, 0), c(1, 1, 0), c(1, 1, 1), c(1, 0, 1));              // x = +lx/2, +x
  if (closed) m.add_quad(c(0, 0, 1), c(1, 0, 1), c(1, 1, 1), c(0, 1, 1));  // lid, +z
  m.flip();
  return m;
}

TriangleMesh make_plate_with_rect_hole(double lx, double ly, double hx, double hy) {
  if (!(lx > 0 && ly > 0 && hx > 0 && hy > 0 && hx < lx && hy < ly))
    throw std::invalid_argument("plate: expected 0 < hole size < plate size in x and y");
  // 3 x 3 grid whose middle cell is the hole; shared vertices keep it conforming.
  const double xs[4] = {-0.5 * lx, -0.5 * hx, 0.5 * hx, 0.5 * lx};
  const double ys[4] = {-0.5 * ly, -0.5 * hy, 0.5 * hy, 0.5 * ly};
  TriangleMesh m;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) m.add_vertex({xs[i], ys[j], 0.0});
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      if (i != 1 || j != 1) m.add_quad(4 * j + i, 4 * j + i + 1, 4 * (j + 1) + i + 1, 4 * (j + 1) + i);
  return m;
}

TriangleMesh make_plate_with_round_hole(double lx, double ly, double r, int n) {
  if (!(lx > 0 && ly > 0 && r > 0 && 2 * r < std::min(lx, ly)) || n < 3)
    throw std::invalid_argument("plate: expected 0 < 2 r < min(lx, ly) and segments >= 3");
  const double ax = 0.5 * lx, ay = 0.5 * ly;
  TriangleMesh m;
  // Hole vertex k on the circle and outer vertex k where the same ray meets the plate's edge.
  std::vector<int> hole(n), outer(n);
  std::vector<double> angle(n + 1);
  for (int k = 0; k <= n; ++k) angle[k] = 2.0 * kPi * k / n;
  for (int k = 0; k < n; ++k) {
    const double c = std::cos(angle[k]), s = std::sin(angle[k]);
    hole[k] = m.add_vertex({r * c, r * s, 0.0});
    const double t = std::min(std::abs(c) > 0 ? ax / std::abs(c) : INFINITY,
                              std::abs(s) > 0 ? ay / std::abs(s) : INFINITY);
    // Snap the coordinate on the edge so the plate's outline is exact.
    Vec3 p{t * c, t * s, 0.0};
    if (std::abs(c) > 0 && ax / std::abs(c) <= t) p.x = std::copysign(ax, c);
    if (std::abs(s) > 0 && ay / std::abs(s) <= t) p.y = std::copysign(ay, s);
    outer[k] = m.add_vertex(p);
  }
  // Plate corners by angle, each attached to the sector it falls strictly inside.
  const double corner_angle[4] = {std::atan2(ay, ax), kPi - std::atan2(ay, ax), kPi + std::atan2(ay, ax),
                                  2 * kPi - std::atan2(ay, ax)};
  const Vec3 corner[4] = {{ax, ay, 0}, {-ax, ay, 0}, {-ax, -ay, 0}, {ax, -ay, 0}};
  for (int k = 0; k < n; ++k) {
    // Sector k is the convex polygon hole_k, outer_k, corners..., outer_k+1, hole_k+1: a fan
    // from hole_k triangulates it counter-clockwise (+z normal).
    std::vector<int> chain{outer[k]};
    for (int q = 0; q < 4; ++q)
      if (corner_angle[q] > angle[k] && corner_angle[q] < angle[k + 1] && !(m.vertices[outer[k]] == corner[q]) &&
          !(m.vertices[outer[(k + 1) % n]] == corner[q]))
        chain.push_back(m.add_vertex(corner[q]));
    chain.push_back(outer[(k + 1) % n]);
    chain.push_back(hole[(k + 1) % n]);
    for (std::size_t q = 0; q + 1 < chain.size(); ++q) m.add_triangle(hole[k], chain[q], chain[q + 1]);
  }
  return m;
}

}  // namespace mpdem
