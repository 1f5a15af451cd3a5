// The trapezoidal rule's end-state update (integrate/trapezoidal_update.hpp) against its closed
// form (physics.md section 9, thesis (134)-(138)) and its norm terms against direct sums, for a
// particle count that leaves a partial group of lanes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <vector>

#include "integrate/trapezoidal_update.hpp"

using namespace mpdem;

namespace {

constexpr std::size_t kN = 1003;  // not a multiple of kUpdateLanes
constexpr double kDt = 1e-4, kPhi = 0.5;

Vec3 vec(std::size_t i, double s) {
  const double t = static_cast<double>(i);
  return {s * std::sin(t + 0.1), s * std::cos(1.3 * t), s * (0.5 - std::sin(0.7 * t))};
}

// Start state, start rates and end rates of kN particles; particle 5 fixed.
struct Arrays {
  std::vector<Vec3> x, v, w, alpha, xp, vp, wp, alphap, x0, v0, w0, a0, b0, force, torque;
  std::vector<double> T, Tp, T0, h0, mass, inertia, radius, heat;
  std::vector<int> material;
  std::vector<double> capacity{800.0, 450.0};  // J/(kg K)
  std::vector<std::uint8_t> fixed;

  Arrays() {
    for (std::size_t i = 0; i < kN; ++i) {
      x0.push_back(vec(i, 0.01));
      v0.push_back(vec(i + 7, 0.2));
      w0.push_back(vec(i + 11, 3.0));
      a0.push_back(vec(i + 13, 9.0));
      b0.push_back(vec(i + 17, 40.0));
      mass.push_back(1e-3 * (1.0 + 0.1 * static_cast<double>(i % 5)));
      inertia.push_back(4e-10 * (1.0 + 0.2 * static_cast<double>(i % 3)));
      radius.push_back(1e-3 * (1.0 + 0.05 * static_cast<double>(i % 4)));
      force.push_back(mass.back() * vec(i + 19, 8.0));
      torque.push_back(inertia.back() * vec(i + 23, 30.0));
      T0.push_back(300.0 + static_cast<double>(i % 9));
      h0.push_back(0.5 * std::sin(static_cast<double>(i)));
      heat.push_back(1e-3 * std::cos(static_cast<double>(i)));
      material.push_back(static_cast<int>(i % 2));
      fixed.push_back(i == 5 ? 1 : 0);
    }
    x = x0, v = v0, w = w0, T = T0;
    xp = vp = wp = alphap = alpha = std::vector<Vec3>(kN);
    Tp = std::vector<double>(kN);
  }
  // What the integrator does after each update: the new iterate (written over y_(K-2)) becomes
  // the state, and the state the previous iterate. Temperatures only when they are iterated.
  void swap_iterates(bool thermal) {
    x.swap(xp), v.swap(vp), w.swap(wp), alpha.swap(alphap);
    if (thermal) T.swap(Tp);
  }
  // The predictor writes the state's arrays (TrapezoidalIntegrator::update).
  UpdateArrays predictor_view() {
    UpdateArrays a = view();
    a.x2 = x.data(), a.v2 = v.data(), a.w2 = w.data(), a.alpha2 = alpha.data(), a.T2 = T.data();
    return a;
  }
  UpdateArrays view() {
    return {x.data(),        v.data(),      w.data(),      alpha.data(),
            T.data(),        xp.data(),     vp.data(),     wp.data(),
            alphap.data(),   Tp.data(),     x0.data(),     v0.data(),
            w0.data(),       T0.data(),     a0.data(),     b0.data(),
            h0.data(),       force.data(),  torque.data(), mass.data(),
            inertia.data(),  radius.data(), heat.data(),   material.data(),
            capacity.data(), fixed.data(),  kDt,           kPhi,
            nullptr,         nullptr,       1.0,           x0.data()};
  }
};

double rel(const Vec3& a, const Vec3& b) { return norm(a - b) / std::max(norm(b), 1e-300); }

}  // namespace

TEST(TrapezoidalUpdate, PredictorAndIterationFollowTheClosedForm) {
  Arrays s;
  const double predicted_far = predict_range<true, false, true>(s.predictor_view(), 0, kN);
  double direct_far = 0.0;  // the largest squared displacement from xb (= x0 here)
  for (std::size_t i = 0; i < kN; ++i) direct_far = std::max(direct_far, norm2(s.x[i] - s.x0[i]));
  EXPECT_EQ(predicted_far, direct_far);
  EXPECT_GT(direct_far, 0.0);
  for (std::size_t i = 0; i < kN; ++i) {
    if (i == 5) continue;
    // Constant rates over the step: v = v0 + dt a0, x = x0 + dt v0 + phi dt^2 a0.
    EXPECT_LT(rel(s.v[i], s.v0[i] + kDt * s.a0[i]), 1e-15) << i;
    EXPECT_LT(rel(s.x[i], s.x0[i] + kDt * s.v0[i] + kPhi * kDt * kDt * s.a0[i]), 1e-15) << i;
    EXPECT_LT(rel(s.alpha[i], kDt * s.w0[i] + kPhi * kDt * kDt * s.b0[i]), 1e-14) << i;
    EXPECT_EQ(s.xp[i], Vec3{});  // the arrays of the iterate before are not written
  }
  const std::vector<Vec3> x1 = s.x, v1 = s.v, w1 = s.w, alpha1 = s.alpha;
  EXPECT_EQ(s.x[5], s.x0[5] + kDt * s.v0[5]);
  EXPECT_EQ(s.v[5], s.v0[5]);
  UpdateLanes lane = {};
  FarLanes far = {};
  update_range<true, false, true>(s.view(), 0, kN, lane, far);
  s.swap_iterates(false);
  direct_far = 0.0;
  for (std::size_t i = 0; i < kN; ++i) direct_far = std::max(direct_far, norm2(s.x[i] - s.x0[i]));
  EXPECT_EQ(*std::max_element(std::begin(far), std::end(far)), direct_far);
  double dx2 = 0.0, dv2 = 0.0, xx02 = 0.0, dalpha2 = 0.0, dw2 = 0.0;  // direct sums over the free particles
  for (std::size_t i = 0; i < kN; ++i) {
    if (i == 5) continue;
    const Vec3 a1 = s.force[i] / s.mass[i];
    const Vec3 v = s.v0[i] + kDt * ((1.0 - kPhi) * s.a0[i] + kPhi * a1);
    EXPECT_LT(rel(s.v[i], v), 1e-15) << i;
    EXPECT_LT(rel(s.x[i], s.x0[i] + kDt * ((1.0 - kPhi) * s.v0[i] + kPhi * v)), 1e-15) << i;
    EXPECT_EQ(s.xp[i], x1[i]);  // the iterate became the previous one
    EXPECT_EQ(s.vp[i], v1[i]);
    EXPECT_EQ(s.wp[i], w1[i]);
    EXPECT_EQ(s.alphap[i], alpha1[i]);
    EXPECT_EQ(s.T[i], s.T0[i]);  // not thermal: T stays
    dx2 += norm2(s.x[i] - x1[i]);
    dv2 += norm2(s.v[i] - v1[i]);
    xx02 += norm2(s.x[i] - s.x0[i]);
    dalpha2 += norm2(s.alpha[i] - alpha1[i]);
    dw2 += norm2(s.w[i] - w1[i]);
  }
  const auto lanes = [&](int term) {
    double sum = 0.0;
    for (std::size_t l = 0; l < kUpdateLanes; ++l) sum += lane[term][l];
    return sum;
  };
  EXPECT_NEAR(lanes(4 * kPosition), dx2, 1e-12 * dx2);
  EXPECT_NEAR(lanes(4 * kVelocity), dv2, 1e-12 * dv2);
  EXPECT_NEAR(lanes(4 * kPosition + 1), xx02, 1e-12 * xx02);
  EXPECT_NEAR(lanes(4 * kRotation), dalpha2, 1e-12 * dalpha2);
  EXPECT_NEAR(lanes(4 * kAngularVelocity), dw2, 1e-12 * dw2);
  EXPECT_GT(dalpha2, 0.0);
  EXPECT_GT(dx2, 0.0);
  EXPECT_EQ(lanes(4 * kTemperature), 0.0);  // not summed without heat
}

TEST(TrapezoidalUpdate, FixedParticleKeepsItsVelocityAndStaysOutOfTheNorms) {
  Arrays s;
  for (std::size_t i = 0; i < kN; ++i) s.fixed[i] = 1;
  predict_range<true, true, true>(s.predictor_view(), 0, kN);
  for (std::size_t i = 0; i < kN; ++i) EXPECT_NEAR(s.T[i], s.T0[i] + kDt * s.h0[i], 1e-12) << i;
  UpdateLanes lane = {};
  FarLanes far = {};
  update_range<true, true, true>(s.view(), 0, kN, lane, far);
  s.swap_iterates(true);
  for (std::size_t i = 0; i < kN; ++i) {
    EXPECT_EQ(s.v[i], s.v0[i]);
    EXPECT_EQ(s.w[i], s.w0[i]);
    EXPECT_EQ(s.x[i], s.x0[i] + kDt * s.v0[i]);
    // Temperatures are iterated for every particle: T = T0 + dt ((1 - phi) h0 + phi h1).
    const double h1 = s.heat[i] / (s.mass[i] * s.capacity[static_cast<std::size_t>(s.material[i])]);
    EXPECT_NEAR(s.T[i], s.T0[i] + kDt * ((1.0 - kPhi) * s.h0[i] + kPhi * h1), 1e-12) << i;
  }
  for (int term = 0; term < 4 * kTemperature; ++term)
    for (std::size_t l = 0; l < kUpdateLanes; ++l) EXPECT_EQ(lane[term][l], 0.0) << term;
  double t1 = 0.0;
  for (std::size_t l = 0; l < kUpdateLanes; ++l) t1 += lane[4 * kTemperature + 1][l];
  EXPECT_GT(t1, 0.0);
}

// Ranges split anywhere give the same states as one range (the lanes follow the position in
// the range, so the caller's fixed blocks make the sums independent of the thread count).
TEST(TrapezoidalUpdate, SplitRangesGiveTheSameStates) {
  Arrays one, two;
  UpdateLanes a = {}, b = {}, c = {};
  FarLanes fa = {}, fb = {}, fc = {};
  update_range<true, true, false>(one.view(), 0, kN, a, fa);
  update_range<true, true, false>(two.view(), 0, 517, b, fb);
  update_range<true, true, false>(two.view(), 517, kN, c, fc);
  one.swap_iterates(true);
  two.swap_iterates(true);
  for (std::size_t i = 0; i < kN; ++i) {
    EXPECT_EQ(one.x[i], two.x[i]);
    EXPECT_EQ(one.w[i], two.w[i]);
    EXPECT_EQ(one.alpha[i], two.alpha[i]);
    EXPECT_EQ(one.T[i], two.T[i]);
  }
}
