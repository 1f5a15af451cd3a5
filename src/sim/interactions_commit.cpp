// Interactions: the bookkeeping of a committed evaluation (energy and heat balances, physics.md
// section 12), and promote(), which lets the trapezoidal rule's last iteration stand for the
// commit evaluation of the same state (docs/integrators.md, "Commit").
#include "contact/barrier_contacts.hpp"
#include "contact/particle_contacts.hpp"
#include "core/deterministic_sum.hpp"
#include "sim/interactions.hpp"

namespace mpdem {

namespace {
// W, -sum (F.v + T.w) over the fixed particles: the power of what holds them to their motion
// (T.w only with rotation: without it every particle's w is held, unbooked). Summed in fixed
// blocks, so independent of the thread count.
double fixed_particle_power(const Particles& p, bool rotation) {
  return deterministic_block_sums<1>(p.size(), [&](std::size_t lo, std::size_t hi, std::array<double, 1>& acc) {
    for (std::size_t i = lo; i < hi; ++i)
      if (p.fixed[i]) acc[0] -= dot(p.force[i], p.v[i]) + (rotation ? dot(p.torque[i], p.w[i]) : 0.0);
  })[0];
}
}  // namespace

bool Interactions::promote(const Particles& p, const Barriers& b) {
  const bool same = last_.valid && !table_.any_rolling() && last_.reversed == 0 && pp_->kept();
  if (!all_ranks(same)) return false;
  pp_->promote();
  pb_->promote();
  book_commit(p, b, last_.dt);
  return true;
}

void Interactions::book_commit(const Particles& p, const Barriers& b, double dt) {
  const CommitTerms& c = last_;
  // The normal dashpots' and rolling resistance's powers by the trapezoid over the step (the
  // start power is the last commit's), the order of accuracy of both integrators; the
  // tangential spring-dashpot by what each contact took in the step (ContactResult), under
  // friction when it slid, under damping when it stuck; and under friction, what the springs'
  // stored energy lost between the last commit and this step's stiffness k_t(delta), with the
  // springs of contacts that ended (the total spring keeps s as k_t changes, the incremental
  // one k_t s: neither keeps 1/2 k_t |s|^2).
  const double restiffened = stats_.spring_energy - c.spring_before;
  stats_.damping_dissipated += 0.5 * dt * (stats_.damping_power + c.damping_power) + c.sticking_loss;
  stats_.friction_dissipated += 0.5 * dt * (stats_.rolling_power + c.rolling_power) + c.sliding_loss + restiffened;
  stats_.damping_power = c.damping_power;
  stats_.rolling_power = c.rolling_power;
  // The barriers' loads are this evaluation's: the power their motion puts into the particles.
  double drive = 0.0;  // W (0 for a resting element)
  for (std::size_t e = 0; e < b.size(); ++e) drive += b.drive_power(e);
  stats_.barrier_work += 0.5 * dt * (stats_.drive_power + drive);
  stats_.drive_power = drive;
  // A fixed particle's velocity is held against the force and torque acting on it (contacts
  // and fields): the holding force -F does the work -F.v (and -T.w) on the system.
  const double held = p.any_fixed() ? fixed_particle_power(p, model_.params.analysis.rotation) : 0.0;  // W
  stats_.fixed_work += 0.5 * dt * (stats_.fixed_power + held);
  stats_.fixed_power = held;
  const double pushed = external_.empty()
                            ? 0.0
                            : external_.power(p, policy_.velocity_lag * dt, model_.params.analysis.rotation);  // W
  stats_.external_work += 0.5 * dt * (stats_.external_power + pushed);
  stats_.external_power = pushed;
  stats_.spring_energy = c.spring_after;
  if (heat_) commit_heat(dt);
}

void Interactions::commit_heat(double dt) {
  // The temperature update weights the start and end flows like the integrator does
  // (its policy: trapezoidal 1 - phi and phi, Verlet's explicit Euler the start flow only), so
  // the cumulative sums balance the stored thermal energy exactly.
  const double phi = policy_.heat_weight;
  const double ob = last_.out_barriers, oc = last_.out_convected, orad = last_.out_radiated;  // outward, W
  stats_.heat_to_barriers += dt * ((1.0 - phi) * out_barriers_ + phi * ob);
  stats_.heat_convected += dt * ((1.0 - phi) * out_convected_ + phi * oc);
  stats_.heat_radiated += dt * ((1.0 - phi) * out_radiated_ + phi * orad);
  out_barriers_ = ob;
  out_convected_ = oc;
  out_radiated_ = orad;
}

}  // namespace mpdem
