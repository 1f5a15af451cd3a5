#include "geometry/triangle_closest_point.hpp"

#include <limits>

namespace mpdem {

TriangleClosestPoint closest_point_on_triangle_boundary(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 v[3] = {a, b, c};
  TriangleClosestPoint best{a, Feature::Vertex, 0};
  double best_d2 = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const int k1 = k == 2 ? 0 : k + 1;
    const Vec3& p = v[k];
    const Vec3& q = v[k1];
    const double qs = vertex_ray(x, p, q);  // > 0: beyond p towards q
    const double qe = vertex_ray(x, q, p);  // > 0: beyond q towards p
    TriangleClosestPoint cand;
    if (qs <= 0.0) {
      cand = {p, Feature::Vertex, k};
    } else if (qe <= 0.0) {
      cand = {q, Feature::Vertex, k1};
    } else {
      // qs + qe = |q - p|^2 exactly in real arithmetic; interpolating from the nearer end keeps the
      // point within rounding of the segment even for t close to 0 or 1.
      const double sum = qs + qe;
      cand.point = qs <= qe ? p + (q - p) * (qs / sum) : q + (p - q) * (qe / sum);
      cand.kind = Feature::Edge;
      cand.index = k;
    }
    const double d2 = norm2(x - cand.point);
    if (d2 < best_d2) {
      best_d2 = d2;
      best = cand;
    }
  }
  return best;
}

TriangleClosestPoint closest_point_on_triangle(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c) {
  const TriangleNormal tn = triangle_normal(a, b, c);
  if (edge_side(x, a, b, tn.n) > 0.0 && edge_side(x, b, c, tn.n) > 0.0 && edge_side(x, c, a, tn.n) > 0.0)
    return {project_on_plane(x, a, tn.n), Feature::Face, 0};
  return closest_point_on_triangle_boundary(x, a, b, c);
}

}  // namespace mpdem
