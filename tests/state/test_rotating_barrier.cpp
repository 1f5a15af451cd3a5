// Rotating barriers (state/rotation_law.hpp, state/barriers.hpp): the angle of a constant and of a
// tabulated rate against closed forms, the placement x = u + R (x0 - o) + o of the vertices, the
// surface velocity, and the fastest point that the rebuild rule uses.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "state/barriers.hpp"

using namespace mpdem;

namespace {

const double kNan = std::numeric_limits<double>::quiet_NaN();

// The table of the issue, [[0, 0], [0.5, 6]]: omega = 12 t up to 0.5 s, then 6 rad/s.
RotationLaw ramp() {
  RotationLaw r;
  r.axis = {0.0, 0.0, 1.0};
  r.omega_table = {{0.0, 0.0}, {0.5, 6.0}};
  return r;
}

}  // namespace

// theta = 6 t^2 on the ramp, 1.5 + 6 (t - 0.5) after it (1e-14 relative).
TEST(RotationLaw, TableAngleMatchesClosedForm) {
  const RotationLaw r = ramp();
  for (double t : {0.0, 0.1, 0.25, 0.4999, 0.5, 0.75, 2.0, 10.0}) {
    const double exact = t <= 0.5 ? 6.0 * t * t : 1.5 + 6.0 * (t - 0.5);
    const double rate = t <= 0.5 ? 12.0 * t : 6.0;
    EXPECT_NEAR(r.angle(t), exact, 1e-14 * std::max(1.0, exact)) << t;
    EXPECT_NEAR(r.rate(t), rate, 1e-14 * std::max(1.0, rate)) << t;
  }
}

// Three rows with a first row after t = 0: the rate is held before it, and the angle is the
// integral from 0 (trapezoids on each segment, then the held last rate).
TEST(RotationLaw, TableHeldOutsideItsRows) {
  RotationLaw r;
  r.omega_table = {{0.2, 1.0}, {0.4, 3.0}, {1.0, -1.0}};
  EXPECT_EQ(r.rate(0.0), 1.0);
  EXPECT_EQ(r.rate(5.0), -1.0);
  const double at1 = 0.2 * 1.0 + 0.5 * (1.0 + 3.0) * 0.2 + 0.5 * (3.0 - 1.0) * 0.6;  // rad at t = 1
  EXPECT_NEAR(r.angle(1.0), at1, 1e-15);
  EXPECT_NEAR(r.angle(3.0), at1 - 2.0, 1e-15);
  // Inside a segment: omega = 3 - 4 (t - 0.4) / 0.6 ... integrated from 0.4 to 0.7.
  const double h = 0.3;
  EXPECT_NEAR(r.angle(0.7), 0.2 + 0.4 + h * (3.0 + 0.5 * (-4.0) * h / 0.6), 1e-15);
  EXPECT_TRUE(r.turns());
  RotationLaw still;
  EXPECT_FALSE(still.turns());
  EXPECT_EQ(RotationLaw{}.angle(7.0), 0.0);
}

// A triangle turning about z through (1, 0, 0) while translating along z: its vertices follow
// the rigid motion, its normal turns, its surface moves with omega x (x - pivot) + u'.
TEST(RotatingBarriers, PlacementAndSurfaceVelocity) {
  Barriers b;
  MotionLaw law;
  law.a = {0.0, 0.0, 0.5};
  RotationLaw r;
  r.axis = {0.0, 0.0, 1.0};
  r.origin = {1.0, 0.0, 0.0};
  r.omega = 2.0;
  law.rotation = r;
  ASSERT_TRUE(b.add(1, {2, 0, 0}, {2, 1, 0}, {2, 0, 1}, 0, 1e9, 0.3, law, 0.0, kNan));
  ASSERT_TRUE(b.add(2, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0, 1e9, 0.3, MotionLaw{}, 0.0, kNan));
  ASSERT_TRUE(b.rotating());
  EXPECT_EQ(b.rotations.size(), 1u);
  const double t = 0.3, th = 2.0 * t;
  b.move_to(t);
  const Vec3 v0 = b.vertex(0, 0);  // (2, 0, 0) is 1 from the axis at angle 0
  EXPECT_NEAR(v0.x, 1.0 + std::cos(th), 1e-15);
  EXPECT_NEAR(v0.y, std::sin(th), 1e-15);
  EXPECT_NEAR(v0.z, 0.5 * t, 1e-15);
  const Vec3 n = b.current_normal(0);  // the rest normal (1, 0, 0) turned by th
  EXPECT_NEAR(n.x, b.normal[0].x * std::cos(th), 1e-15);
  EXPECT_NEAR(n.y, b.normal[0].x * std::sin(th), 1e-15);
  const Vec3 u = b.surface_velocity(0, v0);
  EXPECT_NEAR(u.x, -2.0 * std::sin(th), 1e-14);
  EXPECT_NEAR(u.y, 2.0 * std::cos(th), 1e-14);
  EXPECT_NEAR(u.z, 0.5, 1e-15);
  // The still element is untouched, bit for bit.
  EXPECT_EQ(b.vertex(1, 1), (Vec3{1, 0, 0}));
  EXPECT_EQ(b.surface_velocity(1, {5, 5, 5}), (Vec3{}));
  // Fastest point: vertex (2, 1, 0) or (2, 0, 1)? distance from the axis sqrt(2) (the first),
  // so |u'| + omega sqrt(2).
  EXPECT_NEAR(b.max_point_speed(), 0.5 + 2.0 * std::sqrt(2.0), 1e-14);
}

// Torque about the axis and drive power of an element from its loads: a force F at the point p
// gives moment (p - c) x F about the centre c; the torque is ((p - o) x F) . axis and the power
// -F . v_surface(p) (1e-14 relative).
TEST(RotatingBarriers, AxisTorqueAndDrivePower) {
  Barriers b;
  MotionLaw law;
  law.a = {0.1, -0.2, 0.3};
  RotationLaw r;
  r.axis = Vec3{1.0, 2.0, 2.0} / 3.0;
  r.origin = {0.5, -0.5, 0.25};
  r.omega = -3.0;
  law.rotation = r;
  ASSERT_TRUE(b.add(1, {2, 0, 0}, {2, 1, 0}, {2.5, 0, 1}, 0, 1e9, 0.3, law, 0.0, kNan));
  b.move_to(0.7);
  const Vec3 p = (b.vertex(0, 0) + b.vertex(0, 1) * 2.0 + b.vertex(0, 2)) / 4.0;  // a point of the face
  const Vec3 F{0.3, -1.2, 2.0};
  b.force[0] = F;
  b.moment[0] = cross(p - b.centre(0), F);
  const double torque = dot(cross(p - (r.origin + b.offset[0]), F), r.axis);
  const double power = -dot(F, b.surface_velocity(0, p));
  EXPECT_NEAR(b.axis_torque(0), torque, 1e-14 * std::abs(torque));
  EXPECT_NEAR(b.drive_power(0), power, 1e-14 * std::abs(power));
}
