#include "physics/rigid_rotation.hpp"

#include <cmath>
#include <utility>

namespace mpdem {

namespace {

double component(const Vec3& v, int k) { return k == 0 ? v.x : k == 1 ? v.y : v.z; }

// The exact sub-flow of axis k over h: rotation about body axis k by h pi_k / I_k.
Quat axis_flow(const Quat& q, const Vec3& I, const Vec3& L, int k, double h) {
  const double pi_k = component(to_body(q, L), k);
  return rotate_about_body_axis(q, k, h * pi_k / component(I, k));
}

}  // namespace

Quat free_rotation(const Quat& q, const Vec3& I, const Vec3& L, double h) {
  // Two equal moments (I_a = I_b): the free rotation is exact in closed form as a precession of
  // the body about L (rate |L| / I_a) composed with a spin about the symmetry axis s. The
  // spherical case is one rotation by h L / I.
  if (spherical_body(I)) return rotate_by_increment(q, (h / I.x) * L);
  int s = -1;  // the symmetry axis: the one whose moment differs from the two equal ones
  if (I.y == I.z) s = 0;
  else if (I.x == I.z) s = 1;
  else if (I.x == I.y) s = 2;
  if (s >= 0) {
    const double Ia = component(I, (s + 1) % 3), Is = component(I, s);
    const double pi_s = component(to_body(q, L), s);
    // w = L / Ia + pi_s (1/Is - 1/Ia) s_world: the precession about L first (world frame),
    // then the relative spin about the body's own symmetry axis (body frame); they commute.
    const Quat p = rotate_by_increment(q, (h / Ia) * L);
    return rotate_about_body_axis(p, s, h * pi_s * (1.0 / Is - 1.0 / Ia));
  }
  // The axes by ascending moment, a the smallest: a (h/2), b (h/2), c (h), b (h/2), a (h/2). The
  // order sets the error constant: the fastest sub-rotation (smallest moment) outermost is the best
  // of the six orders or close to it, the largest moment outermost up to 30 times worse
  // (tests/physics/test_rigid_rotation.cpp). Templates' moments are ascending already; a scene's
  // `inertia` override need not be.
  int a = 0, b = 1, c = 2;
  if (component(I, b) < component(I, a)) std::swap(a, b);
  if (component(I, c) < component(I, b)) std::swap(b, c);
  if (component(I, b) < component(I, a)) std::swap(a, b);
  Quat r = axis_flow(q, I, L, a, 0.5 * h);
  r = axis_flow(r, I, L, b, 0.5 * h);
  r = axis_flow(r, I, L, c, h);
  r = axis_flow(r, I, L, b, 0.5 * h);
  return axis_flow(r, I, L, a, 0.5 * h);
}

}  // namespace mpdem
