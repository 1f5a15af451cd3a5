#pragma once
// The clumps' bodies under the trapezoidal rule (docs/physics.md "Clumps: rigid-body dynamics"),
// the same fixed point as the spheres' (physics.md section 9) with a body's rates:
//   V = V0 + dt ((1 - phi) A0 + phi A1),            X = X0 + dt ((1 - phi) V0 + phi V)
//   L = L0 + dt ((1 - phi) tau0 + phi tau1),        W = R(q) I^-1 R(q)^T L
//   alpha = dt ((1 - phi) W0 + phi W),              q = q0 rotated by alpha (world increment)
//   T = T0 + dt ((1 - phi) h0 + phi h1)
// with A = F / M, tau the torque about the centre of mass and L the world angular momentum; W
// takes the orientation of the previous iterate (the fixed point makes them consistent). The
// members are placed on their bodies after every iterate; the sphere update holds them (their
// norm terms are the bodies'). The predictor extrapolates the start rates linearly from the last
// accepted step's, as the spheres' (rate_history.hpp); a spherical body's angular rate is
// tau / I (a sphere's, so that a one-member clump follows the sphere), any other's the torque.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/binary_stream.hpp"
#include "integrate/rate_history.hpp"
#include "integrate/step_report.hpp"
#include "model/scene.hpp"
#include "state/particles.hpp"

namespace mpdem {

class TrapezoidalBodies {
 public:
  // Per field: |y_K - y_(K-1)|^2, |y_K - y(t)|^2, |y_K - y_(K-2)|^2, |y_K|^2 (trapezoidal.hpp).
  using Sums = std::array<double, 4 * kFieldCount>;

  void save_start(const Particles& p, const Model& model);
  // The end state from the rates in p.bodies (predictor: the start rates), the members placed;
  // adds the bodies' norm terms to `sums` (not for the predictor).
  void update(Particles& p, const Model& model, double dt, bool predictor, Sums& sums);
  void accept_midpoint(Particles& p, const Model& model);  // y <- (y_K + y_(K-1)) / 2
  void restore_start(Particles& p, const Model& model) const;
  std::size_t free_bodies() const { return free_; }
  // After an accepted step of dt (s): its start rates become the predictor's history.
  void remember(double dt) {
    a_prev_ = a0_;
    r_prev_ = r0_;
    dt_prev_ = dt;
  }
  // Drops the history (bodies were inserted: on every rank at once, so that no rank's predictor
  // uses one where a single rank's would not).
  void forget() {
    a_prev_.clear();
    r_prev_.clear();
  }
  // Keeps the history of the bodies whose keep[b] is true (Bodies::compact, the bodies a sink removed).
  void compact(const std::vector<char>& keep);
  // The history, for checkpoints (section "body_rate_history": the step length, then the rates
  // of the bodies in B's order; none before the first step).
  void save(BinaryWriter& w) const;
  // The same for every rank's bodies: `records` theirs (records()), gathered and sorted by id
  // like the bodies written with them.
  static void save(BinaryWriter& w, double dt_prev, const std::vector<RateRecord>& records);
  // Reads what save wrote for the bodies `ids` (the checkpoint's, in its order) and keeps the
  // history of those in B (a rank's own, on several ranks).
  void restore(BinaryReader& r, std::span<const std::int64_t> ids, const Bodies& B);
  // The history by body id (anchored by it when a body changes rank), and put back onto the rows
  // of B with the step length dt (s; 0: none). A body without a record has no history.
  std::vector<RateRecord> records(const Bodies& B) const;
  void set_records(std::span<const RateRecord> records, const Bodies& B, double dt);

 private:
  // Start state and rates [B]: m, m/s, rad/s, orientation, kg m^2/s, K, m/s^2, N m, K/s, N, W.
  std::vector<Vec3> x0_, v0_, w0_, L0_, a0_, tau0_, f0_;
  std::vector<Vec3> r0_;  // [B] the angular rate: rad/s^2 (tau / I, spherical body) or N m (torque)
  // The last accepted step's start rates [B] (m/s^2; as r0_) and its length (s; 0: none).
  std::vector<Vec3> a_prev_, r_prev_;
  double dt_prev_ = 0.0;
  std::vector<Quat> q0_;
  std::vector<double> T0_, h0_, heat0_;
  // Iterates y_(K-1) and y_(K-2) [B] (m, m/s, rad/s, rad, K), and the rotation increment alpha.
  std::vector<Vec3> xp_, vp_, wp_, alphap_, xpp_, vpp_, wpp_, alphapp_, alpha_;
  std::vector<double> Tp_, Tpp_;
  std::size_t free_ = 0;
};

}  // namespace mpdem
