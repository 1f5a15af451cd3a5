// The barrier broad phase with elements switched on and off (Barriers::active): a switched-off
// element is nobody's candidate, and any change of the set of active elements since the build
// makes the barrier displacement infinite (the lists are rebuilt at the first evaluation that
// sees it), while the displacement of an inactive element does not count.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "neighbor/barrier_broadphase.hpp"
#include "state/barriers.hpp"

using namespace mpdem;

namespace {

const double kNan = std::numeric_limits<double>::quiet_NaN();

// Two horizontal triangles under the particle at the origin: element 0 always on, element 1 (wide
// enough to stay under it) on for [0.2, 0.4) and moving fast along x.
Barriers two_floors() {
  Barriers b;
  MotionLaw gate;
  gate.active_from = 0.2;
  gate.active_until = 0.4;
  gate.a = {10.0, 0.0, 0.0};
  b.add(1, {-1, -1, -0.01}, {1, -1, -0.01}, {0, 1, -0.01}, 0, 1e7, 0.3, MotionLaw{}, 0.0, kNan);
  b.add(2, {-10, -1, -0.011}, {10, -1, -0.011}, {0, 1, -0.011}, 0, 1e7, 0.3, gate, 0.0, kNan);
  return b;
}

std::vector<std::uint32_t> candidates_at(BarrierBroadphase& broad, Barriers& b, double t) {
  const std::vector<Vec3> x{{0.0, 0.0, 0.0}};
  const std::vector<double> r{0.01};
  b.move_to(t);
  broad.build(x, r, b, 0.002);
  const auto c = broad.candidates(0);
  return {c.begin(), c.end()};
}

}  // namespace

TEST(TimedBroadphase, InactiveElementsAreNobodysCandidate) {
  Barriers b = two_floors();
  BarrierBroadphase broad;
  EXPECT_EQ(candidates_at(broad, b, 0.1), (std::vector<std::uint32_t>{0}));
  EXPECT_EQ(broad.num_elements(), 2u);  // the lists still know every element
  EXPECT_EQ(candidates_at(broad, b, 0.2), (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(candidates_at(broad, b, 0.4), (std::vector<std::uint32_t>{0}));
}

TEST(TimedBroadphase, SwitchForcesARebuild) {
  Barriers b = two_floors();
  BarrierBroadphase broad;
  candidates_at(broad, b, 0.0);  // built with element 1 off
  b.move_to(0.19);
  EXPECT_EQ(broad.max_barrier_displacement(b), 0.0);  // element 1 moved 1.9 m, but is off
  EXPECT_FALSE(broad.needs_rebuild(b, 0.0));
  b.move_to(0.2);  // switches on
  EXPECT_EQ(broad.max_barrier_displacement(b), HUGE_VAL);
  EXPECT_TRUE(broad.needs_rebuild(b, 0.0));
  candidates_at(broad, b, 0.3);  // built with it on
  b.move_to(0.3);
  EXPECT_FALSE(broad.needs_rebuild(b, 0.0));
  b.move_to(0.4);  // switches off
  EXPECT_TRUE(broad.needs_rebuild(b, 0.0));
}
