// Rotations: rescaled Rodrigues composition (7) against rotation matrices (6), and the
// quaternion accumulation of step increments for a long constant spin (physics.md section 2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "core/rotation.hpp"
#include "sim/simulation.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;

namespace {
double max_abs_diff(const Mat3& a, const Mat3& b) {
  double d = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) d = std::max(d, std::abs(a[i][j] - b[i][j]));
  return d;
}
Vec3 random_vec(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return {u(rng), u(rng), u(rng)};
}
}  // namespace

TEST(Rodrigues, MatrixIsARotation) {
  std::mt19937_64 rng(1);
  for (int k = 0; k < 200; ++k) {
    const Mat3 q = rodrigues_matrix(random_vec(rng, 3.0));
    Mat3 qt{};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) qt[i][j] = q[j][i];
    const Mat3 id{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    EXPECT_LT(max_abs_diff(mat_multiply(q, qt), id), 1e-13);  // orthogonal to round-off
  }
}

TEST(Rodrigues, AngleAndAxis) {
  // alpha = 2 tan(theta/2) e rotates by theta about e: (1,0,0) about z by 60 degrees.
  const double theta = std::numbers::pi / 3.0;
  const Vec3 r = mat_apply(rodrigues_matrix({0, 0, 2.0 * std::tan(theta / 2.0)}), {1, 0, 0});
  EXPECT_NEAR(r.x, std::cos(theta), 1e-15);
  EXPECT_NEAR(r.y, std::sin(theta), 1e-15);
  EXPECT_NEAR(r.z, 0.0, 1e-15);
}

TEST(Rodrigues, CompositionEqualsMatrixProduct) {
  std::mt19937_64 rng(2);
  for (int k = 0; k < 1000; ++k) {
    const Vec3 a1 = random_vec(rng, 1.5), a2 = random_vec(rng, 1.5);
    if (std::abs(4.0 - dot(a1, a2)) < 0.5) continue;  // (7) is singular when the composite angle is pi
    const Mat3 expected = mat_multiply(rodrigues_matrix(a2), rodrigues_matrix(a1));
    EXPECT_LT(max_abs_diff(rodrigues_matrix(rodrigues_compose(a1, a2)), expected), 1e-12);
    // The quaternion path used for accumulation agrees with the same product.
    const Quat q = quat_multiply(quat_from_rodrigues(a2), quat_from_rodrigues(a1));
    EXPECT_LT(max_abs_diff(quat_matrix(q), expected), 1e-12);
  }
}

TEST(Rodrigues, RotationVectorConversion) {
  std::mt19937_64 rng(3);
  for (int k = 0; k < 200; ++k) {
    const Vec3 th = random_vec(rng, 1.0);
    const double a = norm(th);
    const Vec3 e = th / a;
    // Rodrigues' rotation formula for angle a about e, applied to a random vector.
    const Vec3 v = random_vec(rng, 1.0);
    const Vec3 expected = v * std::cos(a) + cross(e, v) * std::sin(a) + e * (dot(e, v) * (1 - std::cos(a)));
    const Vec3 got = mat_apply(rodrigues_matrix(rodrigues_from_rotation_vector(th)), v);
    EXPECT_LT(norm(got - expected), 1e-14);
  }
  // Tiny increments go through the series branch continuously.
  const Vec3 small{1e-6, -2e-6, 0.5e-6};
  EXPECT_NEAR(norm(rodrigues_from_rotation_vector(small)), 2.0 * std::tan(0.5 * norm(small)), 1e-20);
}

// A free sphere spinning at constant w for 10 turns has the analytic orientation.
TEST(Rotation, ConstantSpinTenTurns) {
  for (Integrator integ : {Integrator::Trapezoidal, Integrator::Verlet}) {
    const Vec3 axis = Vec3{1.0, 2.0, 2.0} / 3.0;
    const double omega = 7.0;                                          // rad/s
    const double t_end = 10.0 * 2.0 * std::numbers::pi / omega + 0.3;  // 10 turns and a bit
    const int steps = 2000;
    Scene s = test::make_scene(t_end / steps, t_end);
    s.model.params.time.integrator = integ;
    s.model.params.fields.gravity = {};
    test::add_particle(s, 1, 0.01, {}, {}, omega * axis);
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    for (int k = 0; k < steps; ++k) sim.advance(t_end / steps);
    const double a = omega * sim.time();
    const Vec3 body{0.3, -0.5, 0.8};
    const Vec3 expected = body * std::cos(a) + cross(axis, body) * std::sin(a) +
                          axis * (dot(axis, body) * (1 - std::cos(a)));
    const Vec3 got = mat_apply(quat_matrix(sim.particles().q[0]), body);
    EXPECT_LT(norm(got - expected), 1e-9) << (integ == Integrator::Verlet ? "verlet" : "trapezoidal");
    EXPECT_DOUBLE_EQ(norm(sim.particles().w[0] - omega * axis), 0.0);
  }
}

// The series branch of rotate_by_increment (|theta|^2 < kSeriesAngle2) and its cos/sin branch
// both give the increment's quaternion to round-off: against long double cos/sin of half the
// angle, for angles from 1e-7 rad to well past the series limit (sqrt(kSeriesAngle2) = 0.032 rad).
TEST(Rotation, IncrementSeriesAgreesWithTrigonometry) {
  std::mt19937_64 rng(11);
  const Quat q0 = quat_normalized({0.3, -0.2, 0.9, 0.1});
  double worst = 0.0;
  for (int k = 0; k < 4000; ++k) {
    const double a = std::pow(10.0, -7.0 + 6.5 * static_cast<double>(k) / 4000.0);  // 1e-7 .. 0.3 rad
    Vec3 e = random_vec(rng, 1.0);
    e = e / norm(e);
    const Vec3 th = a * e;
    const long double al = std::sqrt(static_cast<long double>(norm2(th)));
    const long double c = std::cos(0.5L * al), s = std::sin(0.5L * al) / al;
    const long double iw = c, ix = s * th.x, iy = s * th.y, iz = s * th.z;  // increment (w, x, y, z)
    const long double ew = iw * q0.w - ix * q0.x - iy * q0.y - iz * q0.z;
    const long double ex = iw * q0.x + ix * q0.w + iy * q0.z - iz * q0.y;
    const long double ey = iw * q0.y - ix * q0.z + iy * q0.w + iz * q0.x;
    const long double ez = iw * q0.z + ix * q0.y - iy * q0.x + iz * q0.w;
    const Quat got = rotate_by_increment(q0, th);
    const double d = static_cast<double>(
        std::max({std::abs(got.w - ew), std::abs(got.x - ex), std::abs(got.y - ey), std::abs(got.z - ez)}));
    worst = std::max(worst, d);
  }
  // A few units of round-off of unit-sized components (2^-52 = 2.2e-16).
  EXPECT_LT(worst, 1e-15);
}

// quat_from_matrix inverts quat_matrix (up to the sign of q: w >= 0), including rotations by
// about pi where the trace is near -1, and gives the exact quaternion of axis permutations.
TEST(Quaternion, FromMatrixInvertsQuatMatrix) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> angle(0.0, std::numbers::pi);
  for (int k = 0; k < 200; ++k) {
    Vec3 axis = random_vec(rng, 1.0);
    axis = axis / norm(axis);
    const double a = k % 10 == 0 ? std::numbers::pi - 1e-9 * k : angle(rng);
    const Mat3 m = axis_angle_matrix(axis, a);
    const Quat q = quat_from_matrix(m);
    EXPECT_GE(q.w, 0.0);
    EXPECT_NEAR(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z, 1.0, 1e-15);
    EXPECT_LT(max_abs_diff(quat_matrix(q), m), 1e-15);
  }
  const Mat3 cyclic{{{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}};  // x -> y -> z -> x
  const Quat c = quat_from_matrix(cyclic);
  EXPECT_EQ(c.w, 0.5);
  EXPECT_EQ(c.x, 0.5);
  EXPECT_EQ(c.y, 0.5);
  EXPECT_EQ(c.z, 0.5);
  EXPECT_EQ(max_abs_diff(quat_matrix(c), cyclic), 0.0);
  const Mat3 half_turn{{{-1, 0, 0}, {0, 1, 0}, {0, 0, -1}}};  // pi about y
  const Quat h = quat_from_matrix(half_turn);
  EXPECT_EQ(h.w, 0.0);
  EXPECT_EQ(h.y, 1.0);
  EXPECT_EQ(max_abs_diff(quat_matrix(h), half_turn), 0.0);
}
