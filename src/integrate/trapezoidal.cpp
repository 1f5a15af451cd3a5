#include "integrate/trapezoidal.hpp"
#include "core/parallel.hpp"
#include "parallel/gather.hpp"

#include <algorithm>
#include <atomic>
#include <iterator>
#include <cmath>
#include <type_traits>

#include "core/deterministic_sum.hpp"
#include "integrate/trapezoidal_update.hpp"
#include "model/body_members.hpp"

namespace mpdem {

namespace {
// Largest alternation, relative to the field's RMS magnitude, accepted as a two-cycle across a
// force discontinuity (docs/integrators.md); the midpoint is then within half of it.
constexpr double kTwoCycleAmplitude = 1e-2;

// Exchanges one of the state's arrays with `next`: what `next` holds for the owned particles (the
// first `owned` entries) becomes the state's, and the state's values go to `next`. Ghosts (after
// the owned particles) keep their values in the state's array: copied across.
template <class T>
void swap_in(std::vector<T>& state, std::vector<T>& next, std::size_t owned) {
  next.resize(state.size());
  std::copy(state.begin() + static_cast<std::ptrdiff_t>(owned), state.end(),
            next.begin() + static_cast<std::ptrdiff_t>(owned));
  state.swap(next);
}

// to[lo, hi) = from[lo, hi).
template <class T>
void copy_range(const std::vector<T>& from, std::vector<T>& to, std::size_t lo, std::size_t hi) {
  std::copy(from.begin() + static_cast<std::ptrdiff_t>(lo), from.begin() + static_cast<std::ptrdiff_t>(hi),
            to.begin() + static_cast<std::ptrdiff_t>(lo));
}

// The start rates a0 = F/m, b0 = M/I of particles [lo, hi), with restrict pointers so that the
// loop vectorises. A fixed particle's (kFixed: fixed[i] != 0) are zero: nothing accelerates it.
template <bool kFixed>
void start_rates(const Vec3* __restrict force, const Vec3* __restrict torque, const double* __restrict mass,
                 const double* __restrict inertia, const std::uint8_t* __restrict fixed, Vec3* __restrict a0,
                 Vec3* __restrict b0, std::size_t lo, std::size_t hi) {
  for (std::size_t i = lo; i < hi; ++i) {
    const bool held = kFixed && fixed[i] != 0;
    const Vec3 a = force[i] / mass[i], b = torque[i] / inertia[i];
    a0[i] = {held ? 0.0 : a.x, held ? 0.0 : a.y, held ? 0.0 : a.z};
    b0[i] = {held ? 0.0 : b.x, held ? 0.0 : b.y, held ? 0.0 : b.z};
  }
}

// f(std::true_type{}) or f(std::false_type{}): a run-time flag as a template argument.
template <class F>
void with_flag(bool flag, F&& f) {
  if (flag) f(std::true_type{});
  else f(std::false_type{});
}
}  // namespace

void TrapezoidalIntegrator::save_start(Particles& p) {
  const std::size_t n = p.size();
  const bool rotation = params_.analysis.rotation;
  const bool thermal = params_.analysis.thermal;
  // The start state changes hands instead of being copied: the predictor writes the state's arrays
  // anew. Orientations are not saved: they change only when a step is accepted (commit). Without
  // heat transfer nothing changes the temperatures or heat flows.
  swap_in(p.x, x0_, n);
  swap_in(p.v, v0_, n);
  if (rotation) swap_in(p.w, w0_, n);
  if (thermal) swap_in(p.T, T0_, n);
  a0_.resize(n);
  b0_.resize(n);
  h0_.resize(thermal ? n : 0);
  alpha_.resize(n);
  force0_.resize(n);
  torque0_.resize(n);
  heat0_.resize(thermal ? n : 0);
  // The materials' heat capacities, for this step's updates too.
  heat_capacity_.resize(model_.materials.size());
  for (std::size_t m = 0; m < heat_capacity_.size(); ++m) heat_capacity_[m] = model_.materials[m].heat_capacity;
  constexpr std::size_t kChunk = 1024;  // particles per task
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
#pragma omp parallel for schedule(static) if (n > kParallelThreshold)
  for (std::size_t c = 0; c < chunks; ++c) {
    const std::size_t lo = c * kChunk, hi = std::min(n, lo + kChunk);
    copy_range(p.force, force0_, lo, hi);
    copy_range(p.torque, torque0_, lo, hi);
    with_flag(any_fixed_, [&](auto kFixed) {
      start_rates<kFixed()>(p.force.data(), p.torque.data(), p.mass.data(), p.inertia.data(), held_, a0_.data(),
                            b0_.data(), lo, hi);
    });
    if (!thermal) continue;
    copy_range(p.heat, heat0_, lo, hi);
    for (std::size_t i = lo; i < hi; ++i)
      h0_[i] = p.heat[i] / (p.mass[i] * heat_capacity_[static_cast<std::size_t>(p.material[i])]);
  }
}

void TrapezoidalIntegrator::restore_start(Particles& p) const {
  const std::size_t n = p.size();
  const bool rotation = params_.analysis.rotation;
  const bool thermal = params_.analysis.thermal;
#pragma omp parallel for schedule(static) if (n > kParallelThreshold)
  for (std::size_t i = 0; i < n; ++i) {
    p.x[i] = x0_[i];
    p.v[i] = v0_[i];
    if (rotation) p.w[i] = w0_[i];
    p.force[i] = force0_[i];
    p.torque[i] = torque0_[i];
    if (thermal) {
      p.T[i] = T0_[i];
      p.heat[i] = heat0_[i];
    }
  }
}

void TrapezoidalIntegrator::accept_midpoint(Particles& p) {
  const std::size_t n = p.size();
  displacement2_ = -1.0;  // the positions move: the commit's evaluation checks them itself
  const bool rotation = params_.analysis.rotation;
  const bool thermal = params_.analysis.thermal;
#pragma omp parallel for schedule(static) if (n > kParallelThreshold)
  for (std::size_t i = 0; i < n; ++i) {
    p.x[i] = 0.5 * (p.x[i] + xp_[i]);
    p.v[i] = 0.5 * (p.v[i] + vp_[i]);
    if (thermal) p.T[i] = 0.5 * (p.T[i] + Tp_[i]);
    if (rotation) {
      p.w[i] = 0.5 * (p.w[i] + wp_[i]);
      alpha_[i] = 0.5 * (alpha_[i] + alphap_[i]);
      p.q[i] = rotate_by_increment(p.q[i], alpha_[i]);  // p.q is the start orientation until the commit
    }
  }
  if (p.has_bodies()) bodies_.accept_midpoint(p, model_);
}

StepReport TrapezoidalIntegrator::step(Particles& p, Barriers& b, Interactions& f, double t, double dt, int max_iter) {
  EvalRequest req{t + dt, dt, policy(params_).phi, false};
  StepReport rep;
  // Checked once per step: without fixed particles the update never reads their flags. With
  // clumps the members are held like fixed particles: their bodies move them.
  const bool bodies = p.has_bodies();
  if (bodies) p.bodies.index_members(p);
  held_ = bodies ? p.bodies.held.data() : p.fixed.data();
  any_fixed_ = bodies || p.any_fixed();
  free_ = p.size();
  if (any_fixed_)
    for (std::size_t i = 0; i < p.size(); ++i) free_ -= held_[i] ? 1 : 0;
  if (bodies) bodies_.save_start(p, model_);
  free_ += bodies ? bodies_.free_bodies() : 0;
  predict(p, dt, f.build_positions(p, b));
  if (req.phi > 0.0) {  // phi = 0 is explicit: the predictor is the end state
    rep.converged = false;
    for (int k = 1; k <= max_iter && !rep.converged; ++k) {
      req.iteration = k;
      const Sums s = iterate(p, b, f, req);
      ++rep.evaluations;
      test_convergence(p, s, k, rep);
    }
    if (!rep.converged) {
      reject(p, rep);
      return rep;
    }
  }
  commit(p, b, f, req, rep);
  ++rep.evaluations;
  history_.remember(std::span<const std::int64_t>(p.id.data(), p.size()), a0_, b0_, dt);
  if (bodies) bodies_.remember(dt);
  return rep;
}

TrapezoidalIntegrator::Sums TrapezoidalIntegrator::update(Particles& p, double dt, bool predictor,
                                                          const Vec3* x_build) {
  const bool rotation = params_.analysis.rotation;
  const bool thermal = params_.analysis.thermal;
  // The end state from the end-of-step rates in the accumulators, into the arrays of the iterate
  // before the previous one, which then swap with the state's: the state it replaces becomes the
  // previous iterate. The predictor's, from the start rates extrapolated with the previous step's
  // (trapezoidal_update.hpp, rate_history.hpp), goes straight into the state's arrays (save_start
  // took their start values): the first iteration's previous iterate is the predictor, and the
  // one before it is not needed (only the two-cycle test reads it, from the third iteration on).
  UpdateArrays a{p.x.data(),
                 p.v.data(),
                 p.w.data(),
                 alpha_.data(),
                 p.T.data(),
                 xp_.data(),
                 vp_.data(),
                 wp_.data(),
                 alphap_.data(),
                 Tp_.data(),
                 x0_.data(),
                 v0_.data(),
                 w0_.data(),
                 T0_.data(),
                 a0_.data(),
                 b0_.data(),
                 h0_.data(),
                 p.force.data(),
                 p.torque.data(),
                 p.mass.data(),
                 p.inertia.data(),
                 p.radius.data(),
                 p.heat.data(),
                 p.material.data(),
                 heat_capacity_.data(),
                 held_,
                 dt,
                 params_.time.phi};
  if (predictor && history_.align(std::span<const std::int64_t>(p.id.data(), p.size()), a0_, b0_)) {
    a.a_prev = history_.a_prev();
    a.b_prev = history_.b_prev();
    a.stretch = dt / history_.dt();
  }
  a.xb = x_build ? x_build : x0_.data();
  const std::size_t n = p.size();
  const auto swap_iterates = [&] {
    swap_in(p.x, xp_, n);
    swap_in(p.v, vp_, n);
    if (rotation) {
      swap_in(p.w, wp_, n);
      alpha_.swap(alphap_);
    }
    if (thermal) swap_in(p.T, Tp_, n);
  };
  if (predictor) {
    a.x2 = p.x.data(), a.v2 = p.v.data(), a.w2 = p.w.data(), a.alpha2 = alpha_.data(), a.T2 = p.T.data();
    constexpr std::size_t kChunk = 1024;  // particles per call
    const std::size_t chunks = (n + kChunk - 1) / kChunk;
    double far = 0.0;
#pragma omp parallel for schedule(static) reduction(max : far) if (n > kParallelThreshold)
    for (std::size_t c = 0; c < chunks; ++c)
      with_flag(rotation, [&](auto kRotates) {
        with_flag(thermal, [&](auto kThermal) {
          with_flag(any_fixed_, [&](auto kFixed) {
            far = std::max(
                far, predict_range<kRotates(), kThermal(), kFixed()>(a, c * kChunk, std::min(n, (c + 1) * kChunk)));
          });
        });
      });
    displacement2_ = x_build ? far : -1.0;
    if (p.has_bodies()) {
      Sums none{};
      bodies_.update(p, model_, dt, true, none);
      displacement2_ = -1.0;  // the members moved after the measurement: the evaluation checks
    }
    return {};
  }
  std::atomic<double> far{0.0};
  const Sums sums = deterministic_block_sums<kUpdateSums>(n, [&](std::size_t lo, std::size_t hi, Sums& acc) {
    UpdateLanes lane = {};
    FarLanes lane_far = {};
    with_flag(rotation, [&](auto kRotates) {
      with_flag(thermal, [&](auto kThermal) {
        with_flag(any_fixed_,
                  [&](auto kFixed) { update_range<kRotates(), kThermal(), kFixed()>(a, lo, hi, lane, lane_far); });
      });
    });
    for (int k = 0; k < kUpdateSums; ++k)
      for (std::size_t l = 0; l < kUpdateLanes; ++l) acc[static_cast<std::size_t>(k)] += lane[k][l];
    const double block_far = *std::max_element(std::begin(lane_far), std::end(lane_far));
    for (double seen = far.load(std::memory_order_relaxed);
         block_far > seen && !far.compare_exchange_weak(seen, block_far, std::memory_order_relaxed);) {}
  });
  swap_iterates();
  displacement2_ = x_build ? far.load() : -1.0;
  if (p.has_bodies()) {
    Sums with_bodies = sums;
    bodies_.update(p, model_, dt, false, with_bodies);
    displacement2_ = -1.0;
    return with_bodies;
  }
  return sums;
}

void TrapezoidalIntegrator::predict(Particles& p, double dt, const Vec3* x_build) {
  const std::size_t n = p.size();
  save_start(p);
  xp_.resize(n);
  vp_.resize(n);
  wp_.resize(n);
  alphap_.resize(n);
  Tp_.resize(n);
  update(p, dt, true, x_build);
}

TrapezoidalIntegrator::Sums TrapezoidalIntegrator::iterate(Particles& p, Barriers& b, Interactions& f,
                                                           const EvalRequest& req) {
  f.set_measured_displacement(displacement2_);
  f.evaluate(p, b, req);
  return update(p, req.dt, false, f.build_positions(p, b));
}

void TrapezoidalIntegrator::test_convergence(Particles& p, const Sums& local, int k, StepReport& rep) {
  Sums s = local;
  std::size_t free = free_, all_particles = p.size();
  if (comm_ && !comm_->serial()) {
    comm_->sum(s);
    free = static_cast<std::size_t>(comm_->sum(static_cast<std::uint64_t>(free)));
    all_particles = static_cast<std::size_t>(comm_->sum(static_cast<std::uint64_t>(all_particles)));
  }
  const ToleranceParams& tol = params_.tolerance;
  const bool rotation = params_.analysis.rotation;
  const std::array<double, kFieldCount> tols{tol.position, tol.velocity, tol.rotation, tol.angular_velocity,
                                             tol.temperature};
  const std::array<double, kFieldCount> floors{tol.position_floor, tol.velocity_floor, tol.rotation_floor,
                                               tol.angular_velocity_floor, tol.temperature_floor};
  const std::array<bool, kFieldCount> active{true, true, rotation, rotation, params_.analysis.thermal};
  // The mechanical fields' sums hold the free particles only; every temperature is iterated.
  const double inv_free = free > 0 ? 1.0 / static_cast<double>(free) : 0.0;
  const double inv_all = all_particles > 0 ? 1.0 / static_cast<double>(all_particles) : 0.0;
  rep.iterations = k;
  bool all = true, cycle = k >= 3;
  double worst = -1.0;
  for (int fld = 0; fld < kFieldCount; ++fld) {
    if (!active[fld]) continue;
    const double inv_n = fld == kTemperature ? inv_all : inv_free;
    // eps = rms|y_K - y_K-1| / (rms|y_K - y(t)| + floor / TOL): converged when eps <= TOL.
    const double diff = std::sqrt(s[4 * fld] * inv_n);
    const double scale = std::sqrt(s[4 * fld + 1] * inv_n) + floors[fld] / tols[fld];
    const double eps = diff / scale;
    if (k == 1) rep.first_error[fld] = eps;
    rep.last_error[fld] = eps;
    if (!(eps <= tols[fld])) all = false;
    // A two-cycle: y_K = y_(K-2) to tolerance, alternating by less than kTwoCycleAmplitude
    // of the field's RMS magnitude (a larger alternation is divergence: reduce dt).
    if (!(std::sqrt(s[4 * fld + 2] * inv_n) / scale <= tols[fld]) ||
        !(diff <= kTwoCycleAmplitude * std::sqrt(s[4 * fld + 3] * inv_n) + floors[fld]))
      cycle = false;
    if (eps / tols[fld] > worst) {
      worst = eps / tols[fld];
      rep.worst_field = fld;
    }
  }
  if (all) {
    rep.converged = true;
    return;
  }
  // y_K = y_(K-2) but y_K != y_(K-1) by a tiny amount: the iteration alternates across a
  // force discontinuity (contact onset under the nonlinear damping, whose coefficient grows
  // like overlap^(1/4); stick-slip switching) and has no fixed point; the midpoint is within
  // half the alternation of either side. Large alternations are divergence, not this.
  if (cycle) {
    accept_midpoint(p);
    rep.converged = rep.two_cycle = true;
  }
}

void TrapezoidalIntegrator::reject(Particles& p, StepReport& rep) const {
  // Name the particle whose worst field still changed most in the last iteration.
  double biggest = -1.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    double c = 0.0;
    switch (rep.worst_field) {
      case kPosition: c = norm2(p.x[i] - xp_[i]); break;
      case kVelocity: c = norm2(p.v[i] - vp_[i]); break;
      case kRotation: c = norm2(alpha_[i] - alphap_[i]); break;
      case kAngularVelocity: c = norm2(p.w[i] - wp_[i]); break;
      default: c = (p.T[i] - Tp_[i]) * (p.T[i] - Tp_[i]); break;
    }
    if (!std::isfinite(c)) c = INFINITY;
    if (c > biggest) {
      biggest = c;
      rep.worst_particle = p.id[i];
    }
  }
  if (comm_ && !comm_->serial()) {  // the largest change over all ranks, so every rank names it
    struct Worst {
      double change;
      std::int64_t id;
    };
    rep.worst_particle = best_across(*comm_, Worst{biggest, rep.worst_particle}, [](const Worst& a, const Worst& b) {
                           return a.change > b.change;
                         }).first.id;
  }
  restore_start(p);
  if (p.has_bodies()) bodies_.restore_start(p, model_);
}

void TrapezoidalIntegrator::commit(Particles& p, Barriers& b, Interactions& f, const EvalRequest& req,
                                   const StepReport& rep) {
  const std::size_t n = p.size();
  // Orientation of the accepted end state (accept_midpoint has set it for a two-cycle).
  if (params_.analysis.rotation && !rep.two_cycle) {
#pragma omp parallel for schedule(static) if (n > kParallelThreshold)
    for (std::size_t i = 0; i < n; ++i) p.q[i] = rotate_by_increment(p.q[i], alpha_[i]);  // from the start's
  }
  if (p.has_bodies()) place_members(model_.clumps, p);  // a member's orientation is its body's
  EvalRequest end = req;
  end.commit = true;
  end.iteration = 0;
  f.set_measured_displacement(displacement2_);
  f.evaluate(p, b, end);
}

}  // namespace mpdem
