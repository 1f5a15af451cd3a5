#pragma once
// Whether a triangle can be a barrier element. Finite coordinates do not suffice: an edge, the
// centroid, the cross product or its norm can overflow (edges of about 1e77 m and up), and the
// area can underflow to zero (a scale of 1e-200), leaving no normal.
#include <charconv>
#include <cmath>
#include <string>

#include "core/vec3.hpp"

namespace mpdem {

// Smallest |(b - a) x (c - a)| (twice the area, m^2) of a barrier element (Barriers::add).
inline constexpr double kMinTwiceArea = 1e-300;

enum class TriangleFault { None, NonFinite, ZeroArea };

struct TriangleCheck {
  TriangleFault fault = TriangleFault::None;
  std::string what;  // "" for None, else the reason ("vertex 2 is (inf, 0, 0)", "its area overflows")
};

// "(x, y, z)", each the shortest text that reads back exactly.
inline std::string vec_text(const Vec3& v) {
  std::string s = "(";
  for (int k = 0; k < 3; ++k) {
    char buf[32];
    s.append(buf, std::to_chars(buf, buf + sizeof buf, v[k]).ptr);
    s += k < 2 ? ", " : ")";
  }
  return s;
}

inline TriangleCheck check_triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 v[3] = {a, b, c};
  for (int k = 0; k < 3; ++k)
    if (!isfinite(v[k])) return {TriangleFault::NonFinite, "vertex " + std::to_string(k + 1) + " is " + vec_text(v[k])};
  if (!isfinite((a + b + c) / 3.0)) return {TriangleFault::NonFinite, "its centroid overflows"};
  const Vec3 n = cross(b - a, c - a);
  const double twice_area = norm(n);
  if (!std::isfinite(twice_area)) return {TriangleFault::NonFinite, "its area overflows"};
  if (!(twice_area > kMinTwiceArea)) return {TriangleFault::ZeroArea, "its area is zero"};
  if (!isfinite(n / twice_area)) return {TriangleFault::NonFinite, "its normal is not finite"};
  return {};
}

}  // namespace mpdem
