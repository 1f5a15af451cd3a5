#pragma once
// Generalised trapezoidal rule with fixed-point iterations (physics.md section 9, thesis
// (128)-(145)):
//   y(t+dt) = y(t) + dt [(1-phi) r(t) + phi r(t+dt)]  for v, w, T
//   x(t+dt) = x(t) + dt [(1-phi) v(t) + phi v(t+dt)],   alpha_D = dt [(1-phi) w(t) + phi w(t+dt)]
// phi = 0 is explicit (one evaluation per step); phi > 0 iterates on the end-of-step rates.
#include <array>
#include <cstddef>
#include <vector>

#include "integrate/rate_history.hpp"
#include "integrate/trapezoidal_bodies.hpp"
#include "interact/step_policy.hpp"
#include "integrate/step_report.hpp"
#include "model/params.hpp"
#include "model/scene.hpp"
#include "parallel/communicator.hpp"
#include "interact/interactions.hpp"

namespace mpdem {

class TrapezoidalIntegrator {
 public:
  // The model's parameters, and its materials' heat capacities (looked up every step).
  explicit TrapezoidalIntegrator(const Model& model) : model_(model), params_(model.params) {}
  // The spring increment (64) and the booked heat flows weigh the step's end by phi, like the
  // state update; the increment needs each contact's step-start history.
  static StepPolicy policy(const Params& params) { return {params.time.phi, true, params.time.phi, false, 0.0}; }

  // Advances the particles from t to t + dt. On entry force/torque/heat hold the rates at the
  // current state. On success the arrays hold the accepted end state and its rates (the commit
  // evaluation stores contact history). When the iteration does not converge within max_iter,
  // the start state and its rates are restored and the report says converged = false.
  StepReport step(Particles& p, Barriers& b, Interactions& f, double t, double dt, int max_iter);
  // A run over several ranks: the convergence norms are summed over all of them, so that every
  // rank iterates as often and accepts (or rejects) the same steps.
  void set_communicator(const Communicator* comm) { comm_ = comm; }
  // The predictor's history: the last accepted step's start rates, by particle id.
  RateHistory& rate_history() { return history_; }
  const RateHistory& rate_history() const { return history_; }
  // The clumps' bodies' part of the step (and of the predictor's history).
  TrapezoidalBodies& bodies() { return bodies_; }
  const TrapezoidalBodies& bodies() const { return bodies_; }

 private:
  // Per field: sums of |y_K - y_(K-1)|^2, |y_K - y(t)|^2, |y_K - y_(K-2)|^2 and |y_K|^2.
  using Sums = std::array<double, 4 * kFieldCount>;

  // The four stages of a step:
  void predict(Particles& p, double dt, const Vec3* x_build);                        // end state from the start rates
  Sums iterate(Particles& p, Barriers& b, Interactions& f, const EvalRequest& req);  // evaluate, update
  void test_convergence(Particles& p, const Sums& s, int k, StepReport& rep);        // sets rep.converged
  void commit(Particles& p, Barriers& b, Interactions& f, const EvalRequest& req, const StepReport& rep);
  // After the last iteration failed: names the culprit and restores the start state.
  void reject(Particles& p, StepReport& rep) const;

  // The end state (134)-(138); x_build: the lists' build positions (Interactions::build_positions,
  // null: none), from which the pass measures displacement2_.
  Sums update(Particles& p, double dt, bool predictor, const Vec3* x_build);
  void save_start(Particles& p);  // takes the start state's arrays, see update()
  void restore_start(Particles& p) const;
  void accept_midpoint(Particles& p);  // y <- (y_K + y_(K-1)) / 2

  const Model& model_;
  const Params& params_;
  const Communicator* comm_ = nullptr;  // null: one rank
  // This step's: whether any particle is fixed (update() reads the flags only then), and how many
  // are free (the mechanical fields' norms are over those).
  bool any_fixed_ = false;
  std::size_t free_ = 0;
  // [N] the flags the update reads: Particles::fixed, or with clumps Bodies::held (members too).
  const std::uint8_t* held_ = nullptr;
  // m^2, the largest squared displacement of the positions in p.x from the lists' build positions,
  // measured by the pass that wrote them and handed to the next evaluation; -1: not measured.
  double displacement2_ = -1.0;
  // Start-of-step state and rates [N]
  std::vector<Vec3> x0_, v0_, w0_, a0_, b0_;  // m, m/s, rad/s, m/s^2, rad/s^2 (w0_: with rotation)
  std::vector<double> T0_, h0_;               // K, K/s (with heat transfer)
  std::vector<Vec3> force0_, torque0_;        // N, N m (to restore the rates on failure)
  std::vector<double> heat0_;                 // W (with heat transfer)
  std::vector<Vec3> alpha_;                   // rad, current rotation increment estimate
  // Previous iterate y_(K-1), to recognise a two-cycle (see docs/integrators.md) [N]
  std::vector<Vec3> xp_, vp_, wp_, alphap_;  // m, m/s, rad/s, rad
  std::vector<double> Tp_;                   // K
  RateHistory history_;
  TrapezoidalBodies bodies_;           // the clumps' bodies (scenes with clumps only)
  std::vector<double> heat_capacity_;  // [materials] J/(kg K), the materials' (save_start(), each step)
};

}  // namespace mpdem
