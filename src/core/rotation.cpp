#include "core/rotation.hpp"

#include <cmath>

namespace mpdem {

Mat3 rodrigues_matrix(const Vec3& a) {
  const double c = 4.0 / (4.0 + norm2(a));
  // A = skew(a); A^2 = a a^T - |a|^2 I
  const Mat3 A{{{0.0, -a.z, a.y}, {a.z, 0.0, -a.x}, {-a.y, a.x, 0.0}}};
  const double aa = norm2(a);
  Mat3 q{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const double a2 = a[i] * a[j] - (i == j ? aa : 0.0);
      q[i][j] = (i == j ? 1.0 : 0.0) + c * (A[i][j] + 0.5 * a2);
    }
  }
  return q;
}

Vec3 rodrigues_compose(const Vec3& a1, const Vec3& a2) {
  return (4.0 / (4.0 - dot(a1, a2))) * (a1 + a2 - 0.5 * cross(a1, a2));
}

Quat quat_multiply(const Quat& a, const Quat& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
          a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
          a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

Quat quat_normalized(const Quat& q) {
  const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  return {q.w / n, q.x / n, q.y / n, q.z / n};
}

Mat3 quat_matrix(const Quat& q) {
  const double w = q.w, x = q.x, y = q.y, z = q.z;
  return Mat3{{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
               {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
               {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
}

Quat quat_from_rodrigues(const Vec3& a) {
  return quat_normalized({1.0, 0.5 * a.x, 0.5 * a.y, 0.5 * a.z});
}

Vec3 rodrigues_from_rotation_vector(const Vec3& theta) {
  const double angle = norm(theta);
  // 2 tan(a/2)/a -> 1 + a^2/12 as a -> 0; the series avoids 0/0 at rest.
  const double scale = angle < 1e-4 ? 1.0 + angle * angle / 12.0 : 2.0 * std::tan(0.5 * angle) / angle;
  return scale * theta;
}

Quat rotate_by_increment(const Quat& q, const Vec3& theta) {
  // The increment's unit quaternion (cos(a/2), sin(a/2) theta/a) is what
  // quat_from_rodrigues(rodrigues_from_rotation_vector(theta)) gives, without its tan, square
  // roots and divisions; per particle per step, so it matters. Series below 1e-4 rad (terms of
  // order a^4 are below round-off there) also avoid 0/0 at rest.
  const double a2 = norm2(theta);
  double c = 0.0, s = 0.0;  // cos(a/2), sin(a/2)/a
  if (a2 < 1e-8) {
    c = 1.0 - 0.125 * a2;
    s = 0.5 - a2 / 48.0;
  } else {
    const double a = std::sqrt(a2);
    c = std::cos(0.5 * a);
    s = std::sin(0.5 * a) / a;
  }
  const Quat r = quat_multiply({c, s * theta.x, s * theta.y, s * theta.z}, q);
  // Renormalised so that round-off does not accumulate over millions of steps.
  const double inv = 1.0 / std::sqrt(r.w * r.w + r.x * r.x + r.y * r.y + r.z * r.z);
  return {r.w * inv, r.x * inv, r.y * inv, r.z * inv};
}

Mat3 mat_multiply(const Mat3& a, const Mat3& b) {
  Mat3 c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) c[i][j] += a[i][k] * b[k][j];
  return c;
}

Vec3 mat_apply(const Mat3& m, const Vec3& v) {
  return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
          m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

}  // namespace mpdem
