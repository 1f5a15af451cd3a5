#pragma once
// The trapezoidal rule's end-state update (physics.md section 9, thesis (134)-(138)) over a range
// of particles, with the convergence norms' terms, written so that it vectorises: restrict
// pointers (and `GCC ivdep`, since GCC ignores restrict on struct members), no call, selects
// instead of branches, and one partial sum per vector lane (added in lane order by the caller, so
// the sums do not depend on the thread count).
//
// Per particle, from the start state (x0, v0, w0, T0) and rates (a0, b0, h0) and the end rates
// a1 = F/m, b1 = M/I, h1 (for the predictor: a0 and b0 extrapolated from the previous step's
// start rates, h0):
//   v = v0 + dt ((1 - phi) a0 + phi a1),   x = x0 + dt ((1 - phi) v0 + phi v)
//   w = w0 + dt ((1 - phi) b0 + phi b1),   alpha = dt ((1 - phi) w0 + phi w)
//   T = T0 + dt ((1 - phi) h0 + phi h1)
// A fixed particle keeps v and w and moves by exactly dt v0 (dt ((1 - phi) v + phi v) may round
// differently); it is left out of the mechanical fields' norms.
//
// The new iterate y_K goes into the arrays that held y_(K-2), read just before for the two-cycle
// terms; the caller then swaps those with the state's arrays, so the state holds y_K and the
// swapped-out arrays y_(K-1). Half the stores of copying y_(K-1) aside and writing y_K over it.
#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "core/vec3.hpp"
#include "integrate/step_report.hpp"

namespace mpdem {

inline constexpr std::size_t kUpdateLanes = 8;  // partial sums per norm term
inline constexpr int kUpdateSums = 4 * kFieldCount;

// Per field f, terms 4f..4f+3: |y_K - y_(K-1)|^2, |y_K - y(t)|^2, |y_K - y_(K-2)|^2 and the
// field's magnitude |y_K|^2 (TrapezoidalIntegrator::test_convergence).
using UpdateLanes = double[kUpdateSums][kUpdateLanes];

struct UpdateArrays {
  // The iterate y_(K-1) [N]: m, m/s, rad/s, rad, K (not read by the predictor).
  const Vec3* __restrict x;
  const Vec3* __restrict v;
  const Vec3* __restrict w;
  const Vec3* __restrict alpha;
  const double* __restrict T;
  // y_(K-2) on entry (not read by the predictor), the new iterate y_K on return [N] (same units).
  Vec3* __restrict x2;
  Vec3* __restrict v2;
  Vec3* __restrict w2;
  Vec3* __restrict alpha2;
  double* __restrict T2;
  // The start state and rates [N]: m, m/s, rad/s, K, m/s^2, rad/s^2, K/s.
  const Vec3* __restrict x0;
  const Vec3* __restrict v0;
  const Vec3* __restrict w0;
  const double* __restrict T0;
  const Vec3* __restrict a0;
  const Vec3* __restrict b0;
  const double* __restrict h0;
  // The end rates' sources [N]: N, N m, kg, kg m^2, m, W, material index.
  const Vec3* __restrict force;
  const Vec3* __restrict torque;
  const double* __restrict mass;
  const double* __restrict inertia;
  const double* __restrict radius;
  const double* __restrict heat;
  const int* __restrict material;
  const double* __restrict heat_capacity;  // [materials] J/(kg K) (kThermal only)
  const std::uint8_t* __restrict fixed;    // [N] (kFixed only)
  double dt = 0.0;                         // s
  double phi = 1.0;                        // -
  // The predictor's history (rate_history.hpp): the previous step's start rates [N] m/s^2,
  // rad/s^2, or null (end rates = start rates), and dt / the previous step's length.
  const Vec3* a_prev = nullptr;
  const Vec3* b_prev = nullptr;
  double stretch = 1.0;
  // The neighbour lists' build positions [N] m, from which the passes measure the new positions'
  // largest squared displacement (Interactions::set_measured_displacement); any array of the
  // particles' positions when there is nothing to measure (the result is then not used).
  const Vec3* xb = nullptr;
};

// Largest squared displacement per lane, m^2 (max is exact: its order does not matter).
using FarLanes = double[kUpdateLanes];

// The predictor over particles [lo, hi): the end state from the end rates extrapolated linearly
// from the previous step's start rates, r(t) + stretch (r(t) - r(t - dt_prev)) (without a
// history: the start rates), into the y_K arrays (the caller passes the state's); x, v, w, alpha
// and T are not read. Without kThermal T2 is not written (the temperatures are not iterated).
// Returns the new positions' largest squared displacement from xb (m^2).
template <bool kRotates, bool kThermal, bool kFixed>
double predict_range(const UpdateArrays& a, std::size_t lo, std::size_t hi) {
  const double dt = a.dt, phi = a.phi, keep = 1.0 - phi;
  double far = 0.0;
  for (std::size_t i = lo; i < hi; ++i) {
    const bool held = kFixed && a.fixed[i] != 0;
    const Vec3 x0 = a.x0[i], v0 = a.v0[i], a0 = a.a0[i];
    const Vec3 a1 = a.a_prev ? a0 + a.stretch * (a0 - a.a_prev[i]) : a0;
    const Vec3 v = held ? v0 : v0 + dt * (keep * a0 + phi * a1);
    const Vec3 x = held ? x0 + dt * v0 : x0 + dt * (keep * v0 + phi * v);
    far = std::max(far, norm2(x - a.xb[i]));
    a.x2[i] = x;
    a.v2[i] = v;
    if constexpr (kRotates) {
      const Vec3 w0 = a.w0[i], b0 = a.b0[i];
      const Vec3 b1 = a.b_prev ? b0 + a.stretch * (b0 - a.b_prev[i]) : b0;
      const Vec3 w = held ? w0 : w0 + dt * (keep * b0 + phi * b1);
      a.w2[i] = w;
      a.alpha2[i] = held ? dt * w0 : dt * (keep * w0 + phi * w);
    }
    if constexpr (kThermal) a.T2[i] = a.T0[i] + dt * (keep * a.h0[i] + phi * a.h0[i]);
  }
  return far;
}

// Component by component: a whole-Vec3 store keeps GCC from vectorising the update's loop.
inline void store(Vec3* __restrict p, const Vec3& v) {
  p->x = v.x;
  p->y = v.y;
  p->z = v.z;
}

// One iteration's update of particle i from the end rates, adding its norm terms to lane l.
// Without kThermal, T2 is not written and the temperature terms are not summed (the field is not
// iterated).
template <bool kRotates, bool kThermal, bool kFixed>
[[gnu::always_inline]] inline void update_particle(const UpdateArrays& a, std::size_t i, std::size_t l,
                                                   UpdateLanes& lane, FarLanes& far) {
  const double dt = a.dt, phi = a.phi, keep = 1.0 - phi;
  const bool held = kFixed && a.fixed[i] != 0;
  // The mechanical norms count the free particles.
  const auto add = [&](int term, double value) { lane[term][l] += held ? 0.0 : value; };
  const Vec3 x0 = a.x0[i], v0 = a.v0[i];
  const Vec3 a1 = a.force[i] / a.mass[i];
  const Vec3 vf = v0 + dt * (keep * a.a0[i] + phi * a1);
  const Vec3 v = held ? v0 : vf;
  const Vec3 x = held ? x0 + dt * v0 : x0 + dt * (keep * v0 + phi * v);
  const Vec3 xi = a.x[i], vi = a.v[i];
  add(4 * Field::kPosition, norm2(x - xi));
  add(4 * Field::kPosition + 1, norm2(x - x0));
  add(4 * Field::kPosition + 2, norm2(x - a.x2[i]));
  add(4 * Field::kPosition + 3, norm2(x));
  add(4 * Field::kVelocity, norm2(v - vi));
  add(4 * Field::kVelocity + 1, norm2(v - v0));
  add(4 * Field::kVelocity + 2, norm2(v - a.v2[i]));
  add(4 * Field::kVelocity + 3, norm2(v));
  far[l] = std::max(far[l], norm2(x - a.xb[i]));
  store(a.x2 + i, x);
  store(a.v2 + i, v);
  if constexpr (kRotates) {
    const Vec3 w0 = a.w0[i];
    const Vec3 b1 = a.torque[i] / a.inertia[i];
    const Vec3 wf = w0 + dt * (keep * a.b0[i] + phi * b1);
    const Vec3 w = held ? w0 : wf;
    const Vec3 alpha = held ? dt * w0 : dt * (keep * w0 + phi * w);
    // The rotational fields' magnitudes count the translational ones in the same units
    // (displacement / R, velocity / R): docs/integrators.md, "two-cycles".
    const double inv_r2 = 1.0 / (a.radius[i] * a.radius[i]);  // 1/m^2
    const Vec3 wi = a.w[i], alphai = a.alpha[i];
    add(4 * Field::kRotation, norm2(alpha - alphai));
    add(4 * Field::kRotation + 1, norm2(alpha));
    add(4 * Field::kRotation + 2, norm2(alpha - a.alpha2[i]));
    add(4 * Field::kRotation + 3, (norm2(alpha) + norm2(x - x0) * inv_r2));
    add(4 * Field::kAngularVelocity, norm2(w - wi));
    add(4 * Field::kAngularVelocity + 1, norm2(w - w0));
    add(4 * Field::kAngularVelocity + 2, norm2(w - a.w2[i]));
    add(4 * Field::kAngularVelocity + 3, (norm2(w) + norm2(v) * inv_r2));
    store(a.w2 + i, w);
    store(a.alpha2 + i, alpha);
  }
  if constexpr (kThermal) {
    const double h1 = a.heat[i] / (a.mass[i] * a.heat_capacity[a.material[i]]);
    const double T = a.T0[i] + dt * (keep * a.h0[i] + phi * h1);
    const double Ti = a.T[i], dTp = T - a.T2[i], d0 = T - a.T0[i];
    lane[4 * Field::kTemperature][l] += (T - Ti) * (T - Ti);
    lane[4 * Field::kTemperature + 1][l] += d0 * d0;
    lane[4 * Field::kTemperature + 2][l] += dTp * dTp;
    lane[4 * Field::kTemperature + 3][l] += T * T;
    a.T2[i] = T;
  }
}

// One iteration's update of particles [lo, hi), each particle's norm terms in the lane of its
// position within a group of kUpdateLanes, and the new positions' largest squared displacement
// from xb into far: whole groups (a loop of constant length, which vectorises), then the rest.
template <bool kRotates, bool kThermal, bool kFixed>
void update_range(const UpdateArrays& a, std::size_t lo, std::size_t hi, UpdateLanes& lane, FarLanes& far) {
  std::size_t i0 = lo;
  for (; i0 + kUpdateLanes <= hi; i0 += kUpdateLanes)
#pragma GCC ivdep
    for (std::size_t l = 0; l < kUpdateLanes; ++l) update_particle<kRotates, kThermal, kFixed>(a, i0 + l, l, lane, far);
  for (std::size_t l = 0; i0 < hi; ++i0, ++l) update_particle<kRotates, kThermal, kFixed>(a, i0, l, lane, far);
}

}  // namespace mpdem
