#pragma once
// Closest point of a triangle to a point, with the Voronoi feature (face, edge or vertex) of the
// triangle it lies in. Basis of barrier contact detection (physics.md section 7, Departure: exact
// closest point instead of the thesis's tests (108)-(124)).
//
// The classification uses only two primitive quantities, exposed here so that barrier contact
// detection can re-evaluate them for neighbouring elements with the very same arithmetic:
//   edge side   s = (x - a_k) . (n x (a_k+1 - a_k))  > 0  <=> x projects on the triangle's side of edge k
//   vertex ray  q = (x - v) . (w - v)                > 0  <=> x projects beyond v along the edge v -> w
// Both are orientation independent (n x e points into the triangle for either winding).
#include <cstdint>

#include "core/vec3.hpp"

namespace mpdem {

enum class Feature : std::uint8_t { Face = 0, Edge = 1, Vertex = 2 };

struct TriangleClosestPoint {
  Vec3 point;                    // m, closest point of the closed triangle
  Feature kind = Feature::Face;  // Voronoi region of the triangle containing the query point
  int index = 0;                 // Face: 0; Edge k: 0 a-b, 1 b-c, 2 c-a; Vertex k: 0 a, 1 b, 2 c
};

struct TriangleNormal {
  Vec3 n;               // m^2, unnormalised normal, equal to (b - a) x (c - a) in exact arithmetic
  double scale2 = 0.0;  // m^4, |e_i|^2 |e_j|^2 of the two edges used: bounds |n|^2, sizes rounding
};

// Normal from the two shortest edges: |n| is the same for every pair, but the rounding error of a
// cross product grows with |e_i||e_j|, so this pair keeps needle triangles accurate.
inline TriangleNormal triangle_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e0 = b - a, e1 = c - b, e2 = a - c;
  const double l0 = norm2(e0), l1 = norm2(e1), l2 = norm2(e2);
  // (b-a)x(c-b) = (c-b)x(a-c) = (a-c)x(b-a) = (b-a)x(c-a); drop the longest edge.
  if (l0 >= l1 && l0 >= l2) return {cross(e1, e2), l1 * l2};
  if (l1 >= l2) return {cross(e2, e0), l2 * l0};
  return {cross(e0, e1), l0 * l1};
}

// Edge side s (m^4): positive when x lies on the triangle's side of the line through ea -> eb,
// n being the triangle's (unnormalised) normal.
inline double edge_side(const Vec3& x, const Vec3& ea, const Vec3& eb, const Vec3& n) {
  return dot(x - ea, cross(n, eb - ea));
}

// Vertex ray q (m^2): positive when x projects beyond v along the direction v -> w.
inline double vertex_ray(const Vec3& x, const Vec3& v, const Vec3& w) { return dot(x - v, w - v); }

// Closest point on the three edges (the triangle's boundary). Edge interior when both vertex rays
// of the edge are positive, else the vertex; the nearest of the three candidates wins.
TriangleClosestPoint closest_point_on_triangle_boundary(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c);

// Closest point on the closed triangle (a, b, c). FACE when x projects strictly inside (all three
// edge sides > 0), otherwise the boundary result. Degenerate triangles fall back to the boundary.
TriangleClosestPoint closest_point_on_triangle(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c);

// Orthogonal projection of x onto the plane through a with normal n (n != 0).
inline Vec3 project_on_plane(const Vec3& x, const Vec3& a, const Vec3& n) { return x - n * (dot(x - a, n) / norm2(n)); }

}  // namespace mpdem
