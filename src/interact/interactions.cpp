#include "interact/interactions.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

#include "core/deterministic_sum.hpp"
#include "core/parallel.hpp"
#include "core/scoped_timer.hpp"
#include "contact/barrier_contacts.hpp"
#include "contact/bonds.hpp"
#include "contact/cohesion_reach.hpp"
#include "thermal/heat_transfer.hpp"
#include "field/near_field_forces.hpp"
#include "interact/verlet_drift.hpp"
#include "neighbor/neighbor_search.hpp"
#include "parallel/gather.hpp"
#include "interact/body_forces.hpp"
#include "core/run_error.hpp"
#include "contact/particle_contacts.hpp"
#include "interact/body_sums.hpp"

namespace mpdem {

namespace {
constexpr double kDriftMargin2 = 1.0 + 1e-6;  // -, squared safety factor on predicted drifts
// -, the next step's displacement is taken as this many times dt x the current speed (the speeds
// change within the step; barrier motion may accelerate).
constexpr double kReachFactor = 2.0;

ContactTable table_for(const Model& model) {
  ContactTable t;
  t.build(model);
  return t;
}

// W, -sum (F.v + T.w) over the fixed particles: the power of what holds them to their motion
// (T.w only with rotation: without it every particle's w is held, unbooked). Summed in fixed
// blocks, so independent of the thread count.
double fixed_particle_power(const Particles& p, bool rotation) {
  return deterministic_block_sums<1>(p.size(), [&](std::size_t lo, std::size_t hi, std::array<double, 1>& acc) {
    for (std::size_t i = lo; i < hi; ++i)
      if (p.fixed[i]) acc[0] -= dot(p.force[i], p.v[i]) + (rotation ? dot(p.torque[i], p.w[i]) : 0.0);
  })[0];
}

// True when some particle i in [lo, hi) has |x_i - x_build_i| + t |v_i| > limit (> 0). Only a
// particle with one of the two terms above limit/2 can, and only those pay for the square roots
// (measured: a vectorised loop over all of them was slower).
bool some_reach(const Vec3* __restrict x, const Vec3* __restrict x_build, const Vec3* __restrict v, std::size_t lo,
                std::size_t hi, double t, double limit) {
  const double quarter2 = 0.25 * limit * limit;
  bool out = false;
  for (std::size_t i = lo; i < hi; ++i) {
    const double d2 = norm2(x[i] - x_build[i]), r2 = t * t * norm2(v[i]);
    out = out || ((d2 > quarter2 || r2 > quarter2) && std::sqrt(d2) + std::sqrt(r2) > limit);
  }
  return out;
}
}  // namespace

double default_skin(const Model& model, const Particles& p) {
  if (model.params.neighbor.skin > 0.0) return model.params.neighbor.skin;
  double rmin = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) rmin = i == 0 ? p.radius[i] : std::min(rmin, p.radius[i]);
  // Inlets add particles later (a silo filled from empty): their smallest radius counts too.
  for (const InletSpec& in : model.params.inlets)
    if (const double r = in.radius.smallest(); r > 0.0) rmin = rmin > 0.0 ? std::min(rmin, r) : r;
  return rmin > 0.0 ? 0.2 * rmin : 1e-3;
}

Interactions::Interactions(const Model& model, const Particles& p, const Barriers& b, const StepPolicy& policy)
    : model_(model), policy_(policy), table_(table_for(model)), gaps_(cohesion_gaps(table_, model, p)),
      // The list reaches beyond contact by the near-field cutoff (0 when the near field is off)
      // and as far as cohesive contacts hold (0 without).
      search_(std::make_unique<NeighborSearch>(
          default_skin(model, p), std::max(near_field_extra_range(model.params.near_field, p), gaps_.particles),
          model.params.domain, largest_member_offset(model.clumps))),
      particle_contacts_(std::make_unique<ParticleContacts>(table_, policy.step_start)),
      barrier_contacts_(std::make_unique<BarrierContacts>(table_, b)) {
  particle_contacts_->set_gap(gaps_.particles);
  barrier_contacts_->set_gap(gaps_.barriers, gaps_.cohesive);
  search_->set_barrier_gap(gaps_.barriers);
  if (near_field_enabled(model.params.near_field)) near_ = std::make_unique<NearFieldForces>(model);
  if (model.params.analysis.thermal) heat_ = std::make_unique<HeatTransfer>(model, b);
  search_->set_incoming_index(near_ || heat_);
  if (model.params.bonds.enabled()) {
    bonds_ = std::make_unique<Bonds>(model);
    bonds_->make(p);
    // The halo of a decomposed run reaches every bond's partner, with room for it to stretch,
    // beyond the two largest radii it covers already.
    bond_margin_ = std::max(0.0, 1.25 * bonds_->longest() - 2.0 * largest_radius(model, p));
  }
}

Interactions::~Interactions() = default;

double Interactions::skin() const { return search_->skin(); }

void Interactions::rebuild(Particles& p, const Barriers& b, bool reorder) {
  next_drift_.valid = false;
  // A state that diverged within a step (a trapezoidal iteration, an absurd restored velocity)
  // reaches a rebuild before the step's health scan: say which particle, as the scan would.
  // On several ranks every rank takes part, so that all stop with the same message.
  std::int64_t bad = -1;  // lowest id with a non-finite position
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!isfinite(p.x[i]) && (bad < 0 || p.id[i] < bad)) bad = p.id[i];
  int rank = -1;
  if (comm_) std::tie(bad, rank) = lowest_id_across(*comm_, bad);
  if (bad >= 0)
    throw RunError(fmt::format("particle id {}{} has a non-finite position at t = {:.9g} s (the state diverged "
                               "within the step); reduce time.dt (see `mpdem check` for a recommended step)",
                               bad, rank_note(comm_, rank), b.time));
  heap_policy_.before_rebuild();  // before its first allocation
  if (comm_) {
    rebuild_decomposed(p, b, reorder);
    return;
  }
  search_->release_for_rebuild();
  ParticleContacts::CarriedHistory history = particle_contacts_->carry_history(*search_);
  p.drop_ghosts();
  // Between steps the particles are wrapped into a periodic domain (never within a step: the
  // integrators hold their step-start positions).
  if (reorder) search_->wrap(p);
  std::vector<std::uint32_t> old_index;  // old index of each particle after the rebuild
  if (reorder && p.size() > 1) {
    old_index = search_->spatial_order(p);
    p.permute(old_index);
    barrier_contacts_->permute(old_index);
  } else {
    old_index.resize(p.size());
    for (std::size_t i = 0; i < old_index.size(); ++i) old_index[i] = static_cast<std::uint32_t>(i);
  }
  search_->rebuild(p, b, [&] { particle_contacts_->restore_history(*search_, std::move(history), old_index); });
  stats_.rebuilds = search_->rebuilds();
}

void Interactions::prepare_step(Particles& p, const Barriers& b, double dt) {
  ScopedTimer timer(times_.search);
  heap_policy_.step();
  if (comm_) balance_if_due(p, b);
  defer_loads_ = comm_ != nullptr;  // until the step's totals (end_step_loads)
  predicted_displacement_ = -1.0;
  // On several ranks every decision is taken over all of them (the rebuild is collective).
  if (policy_.drift_known && dt > 0.0 && !any_rank(stale(p, b))) {
    // Every particle's displacement since the build at the step's evaluation within `limit`
    // leaves the barriers their allowance (checked again at that evaluation).
    const double limit = 0.5 * search_->skin() - barrier_reach(b, dt);  // m
    const NextDrift known = next_drift_;
    next_drift_.valid = false;
    // The last step's final pass checked these very drifts (record_next_drift) when it assumed
    // this step's length and no more room than there is now; otherwise one pass here.
    const bool checked = known.valid && known.dt == dt && known.n == p.size() && known.limit <= limit;
    if (all_ranks(limit > 0.0 && (checked ? known.within : drift_within(p, dt, limit, true)))) {
      predicted_displacement_ = limit;
      return;
    }
    rebuild(p, b, true);
    if (all_ranks(limit > 0.0 && drift_within(p, dt, limit, false))) predicted_displacement_ = limit;
    return;
  }
  if (any_rank(rebuild_due(p, b, dt))) rebuild(p, b, true);
}

Interactions::DriftCheck Interactions::next_drift_check(const Particles& p, const Barriers& b, double dt) const {
  if (!policy_.drift_known || !(dt > 0.0) || stale(p, b)) return {};
  const double limit = 0.5 * search_->skin() - barrier_reach(b, dt);  // m
  if (!(limit > 0.0)) return {};
  return {search_->pairs().build_positions().data(), limit * limit / kDriftMargin2, limit, dt};
}

void Interactions::record_next_drift(const DriftCheck& c, const Particles& p, std::size_t beyond) {
  next_drift_ = NextDrift{c.x_build != nullptr, beyond == 0, c.limit, c.dt, p.size()};
}

bool Interactions::stale(const Particles& p, const Barriers& b) const {
  // A rank may hold no particle for a while: that alone does not make its lists stale.
  return (p.size() == 0 && !comm_) || search_->stale(p) || search_->barrier_candidates().num_elements() != b.size();
}

double Interactions::barrier_reach(const Barriers& b, double dt) const {
  if (b.size() == 0) return 0.0;
  // The fastest point of any element (a rotating one's farthest vertex from its axis).
  return search_->barrier_candidates().max_barrier_displacement(b) + kReachFactor * dt * b.max_point_speed();
}

bool Interactions::drift_within(const Particles& p, double dt, double limit, bool since_build) const {
  const std::size_t n = p.size();
  const double lim2 = limit * limit / kDriftMargin2;  // m^2
  constexpr std::size_t kChunk = 1024;                // particles per call
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  const std::uint8_t* fixed = p.any_fixed() ? p.fixed.data() : nullptr;  // the kick leaves these alone
  std::size_t beyond = 0;
#pragma omp parallel for schedule(static) reduction(+ : beyond) if (n > kParallelThreshold)
  for (std::size_t c = 0; c < chunks; ++c)
    beyond += drift_beyond(p.x.data(), since_build ? search_->pairs().build_positions().data() : p.x.data(), p.v.data(),
                           p.force.data(), p.mass.data(), fixed, c * kChunk, std::min(n, (c + 1) * kChunk), dt, lim2);
  return beyond == 0;
}

const Vec3* Interactions::build_positions(const Particles& p, const Barriers& b) const {
  return stale(p, b) || !search_->pairs().built() ? nullptr : search_->pairs().build_positions().data();
}

bool Interactions::rebuild_due(const Particles& p, const Barriers& b, double dt) const {
  const VerletList& list = search_->pairs();
  const std::size_t n = p.size();
  // Never built, or particles or elements added or removed: NeighborSearch's own check says so.
  if (stale(p, b)) return search_->needs_rebuild(p, b);
  // The lists hold while a particle's displacement + the barriers' displacement since the build
  // stays within skin/2. The coming step adds about dt x the current speeds; twice that, since
  // the speeds change within the step, keeps evaluate()'s own rebuilds practically absent.
  const double limit = 0.5 * search_->skin() - barrier_reach(b, dt);  // m, left for the particles
  if (!(limit > 0.0)) return true;
  constexpr std::size_t kChunk = 1024;  // particles per call
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  bool due = false;
#pragma omp parallel for schedule(static) reduction(|| : due) if (n > kParallelThreshold)
  for (std::size_t c = 0; c < chunks; ++c)
    due = due || some_reach(p.x.data(), list.build_positions().data(), p.v.data(), c * kChunk,
                            std::min(n, (c + 1) * kChunk), kReachFactor * dt, limit);
  return due;
}

void Interactions::force_rebuild(Particles& p, const Barriers& b, bool reorder) { rebuild(p, b, reorder); }

void Interactions::evaluate(Particles& p, Barriers& b, const EvalRequest& req) {
  prepare_evaluation(p, b, req);
  double field_power = 0.0;  // W, dissipated by the body forces (interact/body_forces.hpp)
  {
    ScopedTimer timer(times_.fields);
    field_power = start_accumulators(p);
    external_.add_to(p);
  }
  if (near_) {
    ScopedTimer timer(times_.other);
    stats_.near_field_energy = near_->evaluate(p, *search_);
  }
  PairStats pp, pb;
  {
    ScopedTimer timer(times_.pairs);
    pp = particle_contacts_->evaluate(p, *search_, req);
  }
  {
    ScopedTimer timer(times_.barriers);
    pb = barrier_contacts_->evaluate(p, b, *search_, req);
  }
  if (comm_) {
    ScopedTimer timer(times_.exchange);
    reduce_barrier_loads(b);
  }
  if (heat_) {
    ScopedTimer timer(times_.other);
    const HeatFlows h = heat_->evaluate(p, b, *search_);
    if (req.commit) commit_heat(h, req);
  }
  if (bonds_) evaluate_bonds(p, req);
  {
    ScopedTimer timer(times_.exchange);
    search_->fold_ghosts(p);  // what the periodic images received goes to their sources
  }
  if (p.has_bodies()) {
    ScopedTimer timer(times_.other);
    field_power += sum_onto_bodies(p, model_.params.fields, heat_ != nullptr);
  }
  book_evaluation(p, b, req, pp, pb, field_power);
}

void Interactions::prepare_evaluation(Particles& p, Barriers& b, const EvalRequest& req) {
  next_drift_.valid = false;  // the forces change
  b.move_to(req.time);
  table_.build(model_);  // a material or [contact] value edited between steps acts now
  std::fill(b.force.begin(), b.force.end(), Vec3{});
  std::fill(b.moment.begin(), b.moment.end(), Vec3{});
  std::fill(b.pressure.begin(), b.pressure.end(), 0.0);
  {
    // The safety net behind prepare_step. No reordering within a step: the integrators hold
    // their step-start state by particle index.
    ScopedTimer timer(times_.search);
    // prepare_step checked the particles at the positions this evaluation sees (StepPolicy::
    // drift_known), within skin/2 less the barriers' allowance; the barriers, cheap to check,
    // are checked at the evaluation's time.
    const double known = predicted_displacement_;
    predicted_displacement_ = -1.0;
    const bool checked = known >= 0.0 && !stale(p, b);
    // On several ranks that check needs no collective: prepare_step set `known` alike on every
    // rank, whose lists it found fresh (or rebuilt), and the barriers' check reads only what
    // every rank holds alike (the barriers, their state at the last collective build, the skin).
    // Nothing between prepare_step and the step's evaluation changes the particles; should
    // anything do so on one rank, the ranks would disagree on the collective, hence the throw.
    if (comm_ && known >= 0.0 && !checked)
      throw std::logic_error("Interactions::evaluate: the particles changed since prepare_step");
    // Otherwise the particles are checked here, from the displacement the integrator measured
    // when it wrote their positions (set_measured_displacement), or by a pass of their own.
    const double measured = measured_displacement2_;
    measured_displacement2_ = -1.0;
    const bool due = checked           ? b.size() > 0 && search_->barrier_candidates().needs_rebuild(b, known)
                     : measured >= 0.0 ? any_rank(search_->needs_rebuild(p, b, measured))
                                       : any_rank(search_->needs_rebuild(p, b));
    if (due) {
      rebuild(p, b, false);
      ++mid_step_rebuilds_;
    }
  }
  {
    ScopedTimer timer(times_.exchange);
    search_->refresh_ghosts(p);  // periodic images (or other ranks' particles) take their sources' state
  }
}

void Interactions::book_evaluation(const Particles& p, const Barriers& b, const EvalRequest& req, const PairStats& pp,
                                   const PairStats& pb, double field_power) {
  stats_.contacts_pp = pp.contacts;
  stats_.contacts_pb = pb.contacts;
  // An evaluation without the contacts' energies (compute_energies) keeps the last computed ones.
  if (pp.energies) {
    stats_.elastic_energy = pp.elastic_energy + pb.elastic_energy;
    stats_.elastic_magnitude = pp.elastic_magnitude + pb.elastic_magnitude;
  }
  stats_.bridges = pp.bridges + pb.bridges;
  if (req.commit) {
    // Cohesion: what broke held energy the force no longer stores (contact/pair_batch.hpp).
    stats_.cohesion_breaks += pp.breaks + pb.breaks;
    stats_.ruptures += pp.ruptures + pb.ruptures;
    stats_.cohesion_dissipated += pp.cohesion_loss + pb.cohesion_loss;
    // The normal dashpots' and rolling resistance's powers by the trapezoid over the step (the
    // start power is the last commit's), the order of accuracy of both integrators; the
    // tangential spring-dashpot by what each contact took in the step (ContactResult), under
    // friction when it slid, under damping when it stuck; and under friction, what the springs'
    // stored energy lost between the last commit and this step's stiffness k_t(delta), with the
    // springs of contacts that ended (the total spring keeps s as k_t changes, the incremental
    // one k_t s: neither keeps 1/2 k_t |s|^2).
    // Without the ledger ([checks] energy_ledger = false) the steps between log rows have no terms.
    if (model_.params.checks.energy_ledger) {
      const double damping = pp.damping_power + pb.damping_power, rolling = pp.rolling_power + pb.rolling_power;
      const double restiffened = stats_.spring_energy - (pp.spring_before + pb.spring_before);
      stats_.damping_dissipated += 0.5 * req.dt * (stats_.damping_power + damping) + pp.sticking_loss +
                                   pb.sticking_loss;
      stats_.friction_dissipated += 0.5 * req.dt * (stats_.rolling_power + rolling) + pp.sliding_loss +
                                    pb.sliding_loss + restiffened;
      stats_.damping_power = damping;
      stats_.rolling_power = rolling;
      stats_.spring_energy = pp.spring_after + pb.spring_after;
    }
    // The barriers' loads are this evaluation's: the power their motion puts into the particles.
    double drive = 0.0;  // W (0 for a resting element)
    for (std::size_t e = 0; e < b.size(); ++e) drive += b.drive_power(e);
    stats_.barrier_work += 0.5 * req.dt * (stats_.drive_power + drive);
    stats_.drive_power = drive;
    // A fixed particle's velocity is held against the force and torque acting on it (contacts
    // and fields): the holding force -F does the work -F.v (and -T.w) on the system.
    const bool rotation = model_.params.analysis.rotation;
    const double held = (p.any_fixed() ? fixed_particle_power(p, rotation) : 0.0) +
                        (p.has_bodies() ? fixed_body_power(p, rotation) : 0.0);  // W
    stats_.fixed_work += 0.5 * req.dt * (stats_.fixed_power + held);
    stats_.fixed_power = held;
    const double pushed = external_.empty() ? 0.0
                                            : external_.power(p, policy_.velocity_lag * req.dt,
                                                              model_.params.analysis.rotation);  // W
    stats_.external_work += 0.5 * req.dt * (stats_.external_power + pushed);
    stats_.external_power = pushed;
    stats_.field_dissipated += 0.5 * req.dt * (stats_.field_power + field_power);
    stats_.field_power = field_power;
  }
}

void Interactions::commit_heat(const HeatFlows& h, const EvalRequest& req) {
  // The temperature update weights the start and end flows like the integrator does
  // (its policy: trapezoidal 1 - phi and phi, Verlet's explicit Euler the start flow only), so
  // the cumulative sums balance the stored thermal energy exactly.
  const double phi = policy_.heat_weight;
  const double ob = -h.barriers, oc = -h.convection, orad = -h.radiation;  // outward, W
  stats_.heat_to_barriers += req.dt * ((1.0 - phi) * out_barriers_ + phi * ob);
  stats_.heat_convected += req.dt * ((1.0 - phi) * out_convected_ + phi * oc);
  stats_.heat_radiated += req.dt * ((1.0 - phi) * out_radiated_ + phi * orad);
  out_barriers_ = ob;
  out_convected_ = oc;
  out_radiated_ = orad;
}

std::uint64_t Interactions::convection_clamps() const { return heat_ ? heat_->clamped_evaluations() : 0; }

OverlapReport Interactions::max_overlap(const Particles& p, const Barriers& b) const {
  const OverlapReport pp = particle_contacts_->max_overlap();
  const OverlapReport pb = barrier_contacts_->max_overlap(p, b);
  return pb.ratio > pp.ratio ? pb : pp;
}

}  // namespace mpdem
