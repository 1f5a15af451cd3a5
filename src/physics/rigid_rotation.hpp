#pragma once
// Rotation of a rigid body with principal moments I = (I1, I2, I3) (kg m^2, body frame) and
// orientation q (principal frame -> world), docs/physics.md section 18 "Clumps: rigid-body
// dynamics".
//
// Euler's equations in the body frame, I dw'/dt + w' x (I w') = tau', are integrated in the
// form of the angular momentum: the world-frame L = R I R^T w changes only by the torque (the
// integrator's half kicks), and between kicks the body rotates freely. The free rotation over a
// step h is the symmetric splitting of Dullweber, Leimkuhler and McLachlan (J. Chem. Phys. 107
// (1997) 5840): the kinetic energy is sum_k pi_k^2 / (2 I_k) with pi = R^T L, and each term's
// flow is an exact rotation about body axis k by h pi_k / I_k (pi_k is constant along it), composed
// as a (h/2), b (h/2), c (h), b (h/2), a (h/2) with I_a <= I_b <= I_c. Every sub-rotation keeps L
// exactly (up to round-off) and the composition is symplectic and time-reversible: the rotational
// energy error is O(h^2) and bounded (it oscillates, no drift). An axisymmetric or spherical
// body's free rotation is done exactly instead (a sphere: one rotation by h w about the fixed w).
#include "core/rotation.hpp"
#include "core/vec3.hpp"

namespace mpdem {

// Whether the three principal moments (kg m^2) are equal: such a body has no gyroscopic term and
// the integrators move it with a sphere's operations (a one-member clump follows the sphere).
inline bool spherical_body(const Vec3& I) { return I.x == I.y && I.y == I.z; }

// q rotated by the angle a (rad) about its own body axis k (0, 1, 2): q (cos(a/2), sin(a/2) e_k).
inline Quat rotate_about_body_axis(const Quat& q, int k, double a) {
  const double c = std::cos(0.5 * a), s = std::sin(0.5 * a);
  const Quat r{c, k == 0 ? s : 0.0, k == 1 ? s : 0.0, k == 2 ? s : 0.0};
  return renormalized(quat_multiply(q, r));
}

// Body-frame components of a world vector: R^T u.
inline Vec3 to_body(const Quat& q, const Vec3& u) {
  const Mat3 R = quat_matrix(q);
  return {R[0][0] * u.x + R[1][0] * u.y + R[2][0] * u.z, R[0][1] * u.x + R[1][1] * u.y + R[2][1] * u.z,
          R[0][2] * u.x + R[1][2] * u.y + R[2][2] * u.z};
}

// kg m^2/s, world angular momentum R I R^T w of angular velocity w (rad/s, world).
inline Vec3 angular_momentum(const Quat& q, const Vec3& I, const Vec3& w) {
  const Vec3 b = to_body(q, w);
  return mat_apply(quat_matrix(q), Vec3{I.x * b.x, I.y * b.y, I.z * b.z});
}

// rad/s, world angular velocity R I^-1 R^T L of angular momentum L.
inline Vec3 angular_velocity(const Quat& q, const Vec3& I, const Vec3& L) {
  const Vec3 b = to_body(q, L);
  return mat_apply(quat_matrix(q), Vec3{b.x / I.x, b.y / I.y, b.z / I.z});
}

// J, rotational kinetic energy sum_k I_k w'_k^2 / 2.
inline double rotational_energy(const Quat& q, const Vec3& I, const Vec3& w) {
  const Vec3 b = to_body(q, w);
  return 0.5 * (I.x * b.x * b.x + I.y * b.y * b.y + I.z * b.z * b.z);
}

// Orientation after a free rotation of h (s) with world angular momentum L (constant along it).
Quat free_rotation(const Quat& q, const Vec3& I, const Vec3& L, double h);

}  // namespace mpdem
