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

Quat quat_from_matrix(const Mat3& m) {
  const double tr = m[0][0] + m[1][1] + m[2][2];
  Quat q;
  if (tr >= m[0][0] && tr >= m[1][1] && tr >= m[2][2]) {
    const double s = 2.0 * std::sqrt(1.0 + tr);  // 4 w
    q = {0.25 * s, (m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s};
  } else if (m[0][0] >= m[1][1] && m[0][0] >= m[2][2]) {
    const double s = 2.0 * std::sqrt(1.0 + 2.0 * m[0][0] - tr);  // 4 x
    q = {(m[2][1] - m[1][2]) / s, 0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s};
  } else if (m[1][1] >= m[2][2]) {
    const double s = 2.0 * std::sqrt(1.0 + 2.0 * m[1][1] - tr);  // 4 y
    q = {(m[0][2] - m[2][0]) / s, (m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s};
  } else {
    const double s = 2.0 * std::sqrt(1.0 + 2.0 * m[2][2] - tr);  // 4 z
    q = {(m[1][0] - m[0][1]) / s, (m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s};
  }
  if (q.w < 0.0) q = {-q.w, -q.x, -q.y, -q.z};
  return q;
}

Quat quat_from_rodrigues(const Vec3& a) { return quat_normalized({1.0, 0.5 * a.x, 0.5 * a.y, 0.5 * a.z}); }

Vec3 rodrigues_from_rotation_vector(const Vec3& theta) {
  const double angle = norm(theta);
  // 2 tan(a/2)/a -> 1 + a^2/12 as a -> 0; the series avoids 0/0 at rest.
  const double scale = angle < 1e-4 ? 1.0 + angle * angle / 12.0 : 2.0 * std::tan(0.5 * angle) / angle;
  return scale * theta;
}

Mat3 axis_angle_matrix(const Vec3& k, double angle) {
  // R = cos I + sin [k]x + (1 - cos) k k^T
  const double c = std::cos(angle), s = std::sin(angle), C = 1.0 - c;
  return Mat3{{{c + C * k.x * k.x, C * k.x * k.y - s * k.z, C * k.x * k.z + s * k.y},
               {C * k.y * k.x + s * k.z, c + C * k.y * k.y, C * k.y * k.z - s * k.x},
               {C * k.z * k.x - s * k.y, C * k.z * k.y + s * k.x, c + C * k.z * k.z}}};
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
