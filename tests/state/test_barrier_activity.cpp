// Barriers switched on and off (state/motion_law.hpp, state/barriers.hpp): the activity is a
// function of the time, exact at both ends of the window; a law with a time origin (motion_from =
// "start") is the plain law shifted by t_start and rests at its t = 0 place before it; the
// fastest point ignores switched-off elements; a law without origin is bit for bit unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "state/barriers.hpp"

using namespace mpdem;

namespace {

const double kNan = std::numeric_limits<double>::quiet_NaN();

MotionLaw windowed(double from, double until) {
  MotionLaw m;
  m.active_from = from;
  m.active_until = until;
  return m;
}

void add_triangle(Barriers& b, std::int64_t id, const MotionLaw& law) {
  ASSERT_TRUE(b.add(id, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, b.group_index("g"), 1e7, 0.3, law, 0.0, kNan));
}

}  // namespace

// On for t_start <= t < t_end: the evaluation at t_end itself sees the element off.
TEST(BarrierActivity, WindowIsExactAtBothEnds) {
  Barriers b;
  add_triangle(b, 1, windowed(0.0, 0.5));
  add_triangle(b, 2, windowed(0.2, HUGE_VAL));
  add_triangle(b, 3, MotionLaw{});  // always
  ASSERT_TRUE(b.timed());
  EXPECT_EQ(b.timed_elements, 2u);
  const double before_end = std::nextafter(0.5, 0.0), before_start = std::nextafter(0.2, 0.0);
  const struct {
    double t;
    int lid, gate;
  } rows[] = {{0.0, 1, 0}, {before_start, 1, 0}, {0.2, 1, 1}, {before_end, 1, 1}, {0.5, 0, 1}, {1e9, 0, 1}};
  for (const auto& r : rows) {
    b.move_to(r.t);
    EXPECT_EQ(b.active[0], r.lid) << r.t;
    EXPECT_EQ(b.active[1], r.gate) << r.t;
    EXPECT_EQ(b.active[2], 1) << r.t;
  }
  Barriers plain;  // no windows: nothing to follow
  add_triangle(plain, 1, MotionLaw{});
  EXPECT_FALSE(plain.timed());
  EXPECT_EQ(plain.active[0], 1);
}

// motion_from = "start": u(t) = u_plain(t - t_start), held at u_plain(0) (velocity 0) before.
TEST(BarrierActivity, TimeOriginShiftsTheLaw) {
  MotionLaw plain;
  plain.a = {0.0, 0.0, -0.1};
  plain.A = {0.01, 0.0, 0.0};
  plain.w1 = 3.0;
  plain.B = {0.0, 0.02, 0.0};
  plain.w2 = 5.0;
  MotionLaw late = plain;
  late.active_from = 0.3;
  late.since = 0.3;
  for (double t : {0.35, 0.5, 1.0, 2.7}) {
    const Vec3 d = late.displacement(t) - plain.displacement(t - 0.3), v = late.velocity(t) - plain.velocity(t - 0.3);
    EXPECT_EQ(d, (Vec3{})) << t;
    EXPECT_EQ(v, (Vec3{})) << t;
  }
  for (double t : {0.0, 0.1, 0.3}) {
    EXPECT_EQ(late.displacement(t), plain.displacement(0.0)) << t;
    EXPECT_EQ(late.velocity(t), (t < 0.3 ? Vec3{} : plain.velocity(0.0))) << t;
  }
  // Without an origin the law is the literal one, at every time.
  for (double t : {0.0, 0.1, 1.0}) EXPECT_EQ(windowed(0.2, 0.4).displacement(t), MotionLaw{}.displacement(t));

  RotationLaw spin;
  spin.axis = {0.0, 0.0, 1.0};
  spin.omega_table = {{0.0, 0.0}, {0.5, 6.0}};
  RotationLaw late_spin = spin;
  late_spin.since = 0.3;
  EXPECT_EQ(late_spin.angle(0.1), 0.0);
  EXPECT_EQ(late_spin.rate(0.1), 0.0);
  for (double t : {0.3, 0.55, 0.8, 3.0}) {
    EXPECT_EQ(late_spin.angle(t), spin.angle(t - 0.3)) << t;
    EXPECT_EQ(late_spin.rate(t), spin.rate(t - 0.3)) << t;
  }
  EXPECT_FALSE(late_spin == spin);  // distinct laws for Barriers::rotations
}

// The rebuild rule's fastest point: a switched-off element is in no list and does not count.
TEST(BarrierActivity, FastestPointIgnoresInactiveElements) {
  Barriers b;
  MotionLaw slow;
  slow.a = {0.0, 0.0, 0.1};
  MotionLaw fast = windowed(0.0, 0.5);
  fast.a = {0.0, 0.0, 5.0};
  add_triangle(b, 1, slow);
  add_triangle(b, 2, fast);
  b.move_to(0.25);
  EXPECT_DOUBLE_EQ(b.max_point_speed(), 5.0);
  b.move_to(0.5);
  EXPECT_DOUBLE_EQ(b.max_point_speed(), 0.1);
}
