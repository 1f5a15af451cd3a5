#pragma once
// Rotations: the rescaled Rodrigues vector for per-step increments (physics.md section 2,
// thesis (5)-(7)) and unit quaternions for the accumulated orientation (the Departure of
// section 2: alpha is singular at theta = pi, which a rolling particle passes every turn).
#include <array>
#include <cmath>

#include "core/vec3.hpp"

namespace mpdem {

// 3x3 matrix, row-major; orientation output, rotating barriers and tests.
using Mat3 = std::array<std::array<double, 3>, 3>;

// Q(alpha) = I + 4/(4 + |alpha|^2) (A + A^2/2), A = skew(alpha)        (6)
Mat3 rodrigues_matrix(const Vec3& alpha);

// Composition: first a1 then a2 (fixed frame, Q = Q(a2) Q(a1)):
// a = 4/(4 - a1.a2) (a1 + a2 - a1 x a2 / 2)                            (7)
Vec3 rodrigues_compose(const Vec3& a1, const Vec3& a2);

// Unit quaternion (w, x, y, z) = (cos(theta/2), sin(theta/2) e).
struct Quat {
  double w = 1.0, x = 0.0, y = 0.0, z = 0.0;
};

// Rotation b first, then a. Inline: the integrators call it per particle per step.
inline Quat quat_multiply(const Quat& a, const Quat& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

Quat quat_normalized(const Quat& q);
Mat3 quat_matrix(const Quat& q);
// Inverse of quat_matrix for a proper rotation matrix m (orthonormal, det +1): the unit
// quaternion with w >= 0 (Shepperd's method: the largest of 1 + trace and 1 + 2 m_ii - trace
// under the square root, so no component comes from a small difference). Exact for the
// signed permutations whose quaternion components are 0, 1/2 or 1.
Quat quat_from_matrix(const Mat3& m);
// A rescaled Rodrigues vector alpha = 2 tan(theta/2) e is the quaternion (1, alpha/2) up to
// normalisation; exact, no trigonometry.
Quat quat_from_rodrigues(const Vec3& alpha);
// Rescaled Rodrigues vector (5) of the rotation whose rotation vector (angle times unit axis) is
// theta: 2 tan(|theta|/2) theta/|theta|. The step increment (138), dt times an angular velocity,
// is a rotation vector; converting it exactly makes a constant spin exact for any step.
Vec3 rodrigues_from_rotation_vector(const Vec3& theta);
// Orientation after the incremental rotation with rotation vector theta (fixed frame), composed
// after q and renormalised (139); equal to composing the quaternion of the increment's rescaled
// Rodrigues vector, computed directly from theta's angle and axis.
//
// Split in two so that the integrators' per-particle loops vectorise: below kSeriesAngle2 (rad^2)
// the increment's quaternion is a short series (branch-free, rotate_by_small_increment); above,
// cos and sin (rotate_by_increment), which loops call for the rare particles that spin that fast.
// Both give exactly what the one function gives. The series runs to a^6: its first omitted term,
// a^8 / 10321920 at a^2 = 1e-3, is 1e-19, below round-off; 1e-3 rad^2 (|theta| < 0.032 rad)
// covers a 2 mm sphere rolling at 30 m/s with dt = 4e-6 s, so flowing beds stay on the series.
inline constexpr double kSeriesAngle2 = 1e-3;

// Renormalised so that round-off does not accumulate over millions of steps. |r|^2 = 1 + e
// with e of the order of round-off (a product of unit quaternions): one Newton step for
// 1/sqrt(1 + e), 1 - e/2, is exact to O(e^2) without a square root or division.
inline Quat renormalized(const Quat& r) {
  const double n2 = r.w * r.w + r.x * r.x + r.y * r.y + r.z * r.z;
  const double inv = std::abs(n2 - 1.0) < 1e-6 ? 1.5 - 0.5 * n2 : 1.0 / std::sqrt(n2);
  return {r.w * inv, r.x * inv, r.y * inv, r.z * inv};
}

// rotate_by_increment for |theta|^2 < kSeriesAngle2 (the caller checks).
inline Quat rotate_by_small_increment(const Quat& q, const Vec3& theta) {
  const double a2 = norm2(theta);
  // cos(a/2) and sin(a/2)/a: sum_k (-1)^k (a/2)^2k / (2k)!, and (a/2)^2k / (2 (2k+1)!).
  const double c = 1.0 - a2 * (1.0 / 8.0 - a2 * (1.0 / 384.0 - a2 * (1.0 / 46080.0)));
  const double s = 0.5 - a2 * (1.0 / 48.0 - a2 * (1.0 / 3840.0 - a2 * (1.0 / 645120.0)));
  return renormalized(quat_multiply({c, s * theta.x, s * theta.y, s * theta.z}, q));
}

inline Quat rotate_by_increment(const Quat& q, const Vec3& theta) {
  // The increment's unit quaternion (cos(a/2), sin(a/2) theta/a) is what
  // quat_from_rodrigues(rodrigues_from_rotation_vector(theta)) gives, without its tan, square
  // roots and divisions; per particle per step, so it matters. The series also avoids 0/0 at rest.
  const double a2 = norm2(theta);
  if (a2 < kSeriesAngle2) return rotate_by_small_increment(q, theta);
  const double a = std::sqrt(a2);
  const double c = std::cos(0.5 * a), s = std::sin(0.5 * a) / a;
  return renormalized(quat_multiply({c, s * theta.x, s * theta.y, s * theta.z}, q));
}

// Rotation by `angle` (rad) about the unit vector `axis`, right-handed (Rodrigues' formula).
Mat3 axis_angle_matrix(const Vec3& axis, double angle);

Mat3 mat_multiply(const Mat3& a, const Mat3& b);
Vec3 mat_apply(const Mat3& m, const Vec3& v);

}  // namespace mpdem
