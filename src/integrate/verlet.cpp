#include "integrate/verlet.hpp"

#include <algorithm>
#include <cstdint>
#include <exception>

#include "core/deterministic_sum.hpp"
#include "core/parallel.hpp"
#include "integrate/health_scan.hpp"
#include "integrate/rigid_bodies.hpp"
#include "interact/verlet_drift.hpp"

namespace mpdem {

namespace {

// First half kick and drift, and the orientation update, over particles [lo, hi), written so
// that it vectorises: restrict pointers as arguments (an OpenMP region's captured pointers lose
// it), no call, no branch. With kFixed, a fixed particle's kick is zero (its v and w stay as
// given, x advances by dt v); without, `fixed` is not read. Returns how many particles have an
// increment too large for the series (rotation.hpp); the caller rotates those exactly, which
// gives rotate_by_increment's result for every particle.
template <bool kRotation, bool kFixed>
std::size_t kick_drift_range(Vec3* __restrict x, Vec3* __restrict v, Vec3* __restrict w, Quat* __restrict q,
                             const Vec3* __restrict f, const Vec3* __restrict t, const double* __restrict m,
                             const double* __restrict I, const std::uint8_t* __restrict fixed, std::size_t lo,
                             std::size_t hi, double dt) {
  const double half = 0.5 * dt;
  std::size_t fast = 0;
  for (std::size_t i = lo; i < hi; ++i) {
    const double kick = kFixed && fixed[i] ? 0.0 : half;  // s
    v[i] += (kick / m[i]) * f[i];
    x[i] += dt * v[i];
    if constexpr (kRotation) {
      w[i] += (kick / I[i]) * t[i];
      const Vec3 th = dt * w[i];
      const bool small = norm2(th) < kSeriesAngle2;
      const Quat r = rotate_by_small_increment(q[i], th);
      const Quat q0 = q[i];
      q[i] = {small ? r.w : q0.w, small ? r.x : q0.x, small ? r.y : q0.y, small ? r.z : q0.z};
      fast += small ? 0 : 1;
    }
  }
  return fast;
}

// The second half kick over [lo, hi), vectorised like kick_drift_range (kFixed likewise).
template <bool kFixed>
void kick_range(Vec3* __restrict v, Vec3* __restrict w, const Vec3* __restrict f, const Vec3* __restrict t,
                const double* __restrict m, const double* __restrict I, const std::uint8_t* __restrict fixed,
                std::size_t lo, std::size_t hi, double half, bool rotation) {
  for (std::size_t i = lo; i < hi; ++i) v[i] += ((kFixed && fixed[i] ? 0.0 : half) / m[i]) * f[i];
  if (rotation)
    for (std::size_t i = lo; i < hi; ++i) w[i] += ((kFixed && fixed[i] ? 0.0 : half) / I[i]) * t[i];
}

// The first half kick and drift as orphaned work-sharing loops: every thread of a team calls it
// (or one thread outside a region). fast: shared, zero on entry (the fast rotations' count).
template <bool kRotation, bool kFixed>
void kick_drift_in_team(Particles& p, const std::uint8_t* fixed, double dt, std::size_t& fast) {
  constexpr std::size_t kChunk = 1024;  // particles per call
  const std::size_t n = p.size(), chunks = (n + kChunk - 1) / kChunk;
  std::size_t mine = 0;
#pragma omp for schedule(static) nowait
  for (std::size_t c = 0; c < chunks; ++c)
    mine += kick_drift_range<kRotation, kFixed>(p.x.data(), p.v.data(), p.w.data(), p.q.data(), p.force.data(),
                                                p.torque.data(), p.mass.data(), p.inertia.data(), fixed, c * kChunk,
                                                std::min(n, (c + 1) * kChunk), dt);
#pragma omp atomic
  fast += mine;
#pragma omp barrier
  if (fast == 0) return;
#pragma omp for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 th = dt * p.w[i];
    if (!(norm2(th) < kSeriesAngle2)) p.q[i] = rotate_by_increment(p.q[i], th);
  }
}

void kick_drift_in_team(Particles& p, bool rotation, bool any_fixed, const std::uint8_t* held, double dt,
                        std::size_t& fast) {
  if (rotation)
    any_fixed ? kick_drift_in_team<true, true>(p, held, dt, fast) : kick_drift_in_team<true, false>(p, held, dt, fast);
  else
    any_fixed ? kick_drift_in_team<false, true>(p, held, dt, fast)
              : kick_drift_in_team<false, false>(p, held, dt, fast);
}

}  // namespace

StepReport VerletIntegrator::step(Particles& p, Barriers& b, Interactions& f, double t, double dt) {
  const bool rotation = params_.analysis.rotation;
  const bool thermal = params_.analysis.thermal;
  const std::size_t n = p.size();
  const double half = 0.5 * dt;
  // Checked once per step: scenes without fixed particles keep the plain loops. With clumps the
  // member spheres are held too: their motion is their bodies' (integrate/rigid_bodies.hpp).
  const bool bodies = p.has_bodies();
  if (bodies) p.bodies.index_members(p);
  const bool any_fixed = bodies || p.any_fixed();
  const std::uint8_t* held = bodies ? p.bodies.held.data() : p.fixed.data();
  const EvalRequest req{t + dt, dt, policy().phi, true};
  // Second kick, with the health scan of the end state (integrate/health_scan.hpp) and the next step's
  // neighbour-list check (the drift of a step of the same length) in the same pass.
  const FieldParams& fields = params_.fields;
  const DomainParams& domain = params_.domain;
  const bool ledger = params_.checks.energy_ledger;  // without it no energy sum is read (health_scan.hpp)
  Interactions::DriftCheck next;
  const auto kick_scan = [&](std::size_t lo, std::size_t hi, std::array<double, kScanSums + 1>& acc) {
    // A block at a time: the kick vectorises, and the scan then reads what is still in cache.
    const std::uint8_t* fixed = any_fixed ? held : nullptr;
    if (any_fixed)
      kick_range<true>(p.v.data(), p.w.data(), p.force.data(), p.torque.data(), p.mass.data(), p.inertia.data(), fixed,
                       lo, hi, half, rotation);
    else
      kick_range<false>(p.v.data(), p.w.data(), p.force.data(), p.torque.data(), p.mass.data(), p.inertia.data(), fixed,
                        lo, hi, half, rotation);
    if (next.x_build)
      acc[kScanSums] += static_cast<double>(drift_beyond(p.x.data(), next.x_build, p.v.data(), p.force.data(),
                                                         p.mass.data(), fixed, lo, hi, dt, next.lim2));
    std::array<double, kScanSums> s{};
    scan_range(p, lo, hi, fields, domain, s, ledger);
    for (int k = 0; k < kScanSums; ++k) acc[k] += s[k];
  };
  std::size_t fast = 0;  // particles whose rotation increment is too large for the series
  scan_blocks_.resize(sum_blocks(n));
  if (!bodies && !thermal && n > kParallelThreshold && f.team_ready(p)) {
    // The whole step as one parallel region: its threads wake once, not once per pass.
#pragma omp parallel
    {
      kick_drift_in_team(p, rotation, any_fixed, held, dt, fast);
      f.evaluate_in_team(p, b, req, &next);
      if (!f.team_error()) block_sums_in_team<kScanSums + 1>(n, scan_blocks_, kick_scan);
    }
    if (f.team_error()) std::rethrow_exception(f.take_team_error());
  } else {
#pragma omp parallel if (n > kParallelThreshold)
    kick_drift_in_team(p, rotation, any_fixed, held, dt, fast);
    if (bodies) bodies_kick_drift(p, model_.clumps, dt, rotation);
    if (thermal) {
#pragma omp parallel for schedule(static) if (n > kParallelThreshold)
      for (std::size_t i = 0; i < n; ++i)
        p.T[i] += dt * p.heat[i] /
                  (p.mass[i] * model_.materials[static_cast<std::size_t>(p.material[i])].heat_capacity);
      if (bodies) bodies_heat(p, model_.materials, dt);
    }
    f.evaluate(p, b, req);
    if (bodies) {
      p.bodies.index_members(p);  // a rebuild within the evaluation keeps the order, but checks it
      bodies_kick(p, model_.clumps, dt, rotation);
    }
    next = f.next_drift_check(p, b, dt);
#pragma omp parallel if (n > kParallelThreshold)
    block_sums_in_team<kScanSums + 1>(n, scan_blocks_, kick_scan);
  }
  const auto sums = block_total<kScanSums + 1>(scan_blocks_);
  std::array<double, kScanSums> scan{};
  std::copy_n(sums.begin(), kScanSums, scan.begin());
  if (bodies) scan_bodies(p, fields, domain, scan);
  f.record_next_drift(next, p, static_cast<std::size_t>(sums[kScanSums]));
  StepReport rep;
  rep.scan = scan_from_sums(scan);
  rep.scanned = true;
  rep.evaluations = 1;
  return rep;
}

}  // namespace mpdem
