#pragma once
// Test oracle: the closest point of a triangle to a point, computed by brute force, to check
// geometry/triangle_closest_point.hpp and the contact overlaps against. Not used by the engine.
#include <algorithm>
#include <limits>

#include "core/vec3.hpp"

namespace mpdem::test {

// Independent reference: minimum over the face projection (barycentric solve) and the three
// clamped segment projections.
inline Vec3 brute_closest(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 u = b - a, v = c - a, w = x - a;
  const double uu = dot(u, u), uv = dot(u, v), vv = dot(v, v), wu = dot(w, u), wv = dot(w, v);
  const double det = uu * vv - uv * uv;
  const double s = (wu * vv - wv * uv) / det, t = (wv * uu - wu * uv) / det;
  if (s >= 0 && t >= 0 && s + t <= 1) return a + u * s + v * t;
  Vec3 best{};
  double bd = std::numeric_limits<double>::infinity();
  const Vec3 P[3] = {a, b, c};
  for (int k = 0; k < 3; ++k) {
    const Vec3 p = P[k], e = P[(k + 1) % 3] - P[k];
    const double tt = std::clamp(dot(x - p, e) / dot(e, e), 0.0, 1.0);
    const Vec3 q = p + e * tt;
    if (norm2(x - q) < bd) bd = norm2(x - q), best = q;
  }
  return best;
}

}  // namespace mpdem::test
