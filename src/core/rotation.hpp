#pragma once
// Rotations: the rescaled Rodrigues vector for per-step increments (physics.md section 2,
// thesis (5)-(7)) and unit quaternions for the accumulated orientation (the Departure of
// section 2: alpha is singular at theta = pi, which a rolling particle passes every turn).
#include <array>

#include "core/vec3.hpp"

namespace mpdem {

// 3x3 matrix, row-major; only used for orientation output and tests.
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

Quat quat_multiply(const Quat& a, const Quat& b);  // rotation b first, then a
Quat quat_normalized(const Quat& q);
Mat3 quat_matrix(const Quat& q);
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
Quat rotate_by_increment(const Quat& q, const Vec3& theta);

Mat3 mat_multiply(const Mat3& a, const Mat3& b);
Vec3 mat_apply(const Mat3& m, const Vec3& v);

}  // namespace mpdem
