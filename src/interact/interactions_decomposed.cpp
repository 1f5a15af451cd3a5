// Interactions over several ranks (docs/parallel.md): the decomposition's set-up, the collective
// decisions, the rebuild that migrates particles with their contact history keyed by ids, and
// the reductions of the barrier loads (or their deferral to the step's totals) and statistics.
#include <algorithm>
#include <iterator>
#include <span>
#include <vector>

#include "contact/barrier_contacts.hpp"
#include "contact/bonds.hpp"
#include "contact/particle_contacts.hpp"
#include "neighbor/neighbor_search.hpp"
#include "parallel/brick_grid.hpp"
#include "parallel/communicator.hpp"
#include "parallel/load_balance.hpp"
#include "interact/interactions.hpp"

namespace mpdem {

void Interactions::decompose(const Communicator& comm, const BrickGrid& grid, double body_margin) {
  comm_ = &comm;
  // The halo reaches every bond's partner (bond_margin_).
  body_margin += bond_margin_;
  search_->decompose(comm, grid, heat_ != nullptr, body_margin);  // ghosts' temperatures only for heat transfer
}

bool Interactions::any_rank(bool v) const { return comm_ ? comm_->any(v) : v; }

void Interactions::rebuild_decomposed(Particles& p, const Barriers& b, bool reorder) {
  // A pair's history lives on the rank of its lower-id particle, which this rank owns: it is
  // anchored there and travels with it. Barrier contacts travel with their particle.
  std::vector<PairHistory> pairs = particle_contacts_->export_history(p, *search_);
  p.drop_ghosts();
  if (reorder) {
    AttachedRecords pair_records = AttachedRecords::of<PairHistory>();
    for (const PairHistory& h : pairs) pair_records.push(std::min(h.id_first, h.id_second), h);
    AttachedRecords barrier_records = barrier_contacts_->export_records(p);  // (migrate wraps the periodic axes)
    AttachedRecords other = travelling_.take ? travelling_.take() : AttachedRecords{};
    AttachedRecords body_other = body_travelling_.take ? body_travelling_.take() : AttachedRecords{};
    // A bond travels with its lower-id particle.
    AttachedRecords bond_records = AttachedRecords::of<BondRecord>();
    if (bonds_)
      for (const BondRecord& r : bonds_->export_records()) bond_records.push(r.id_i, r);
    std::vector<AttachedRecords*> attached{&pair_records, &barrier_records, &bond_records}, body_attached;
    if (travelling_.take) attached.push_back(&other);
    if (body_travelling_.take) body_attached.push_back(&body_other);
    search_->migrate(p, attached, body_attached);
    if (travelling_.give) travelling_.give(other);
    if (body_travelling_.give) body_travelling_.give(body_other);
    if (p.size() > 1) p.permute(search_->spatial_order(p));
    search_->rebuild(p, b);
    pairs.clear();
    for (std::size_t r = 0; r < pair_records.size(); ++r) pairs.push_back(pair_records.get<PairHistory>(r));
    barrier_contacts_->import_records(p, barrier_records);
    if (bonds_) {
      std::vector<BondRecord> bonds(bond_records.size());
      for (std::size_t r = 0; r < bond_records.size(); ++r) bonds[r] = bond_records.get<BondRecord>(r);
      bonds_->import_records(std::move(bonds));
    }
  } else {
    // Within a step: the owned particles keep their indices (and barrier records); the ghosts change.
    search_->rebuild(p, b);
  }
  particle_contacts_->import_history(p, *search_, std::move(pairs));
  stats_.rebuilds = search_->rebuilds();
}

void Interactions::balance_if_due(Particles& p, const Barriers& b) {
  const ParallelParams& prm = model_.params.parallel;
  if (prm.balance_every <= 0 || ++steps_since_balance_ < static_cast<std::uint64_t>(prm.balance_every)) return;
  steps_since_balance_ = 0;
  double cost = 0.0;
  if (prm.balance_cost == BalanceCost::Time) {
    // Computing only: the waits for the other ranks are in times_.exchange and times_.search.
    const double busy = times_.fields + times_.pairs + times_.barriers + times_.other;  // s
    cost = busy - busy_at_balance_;
    busy_at_balance_ = busy;
  } else {
    cost = static_cast<double>(p.size() + search_->pairs().num_pairs());
  }
  imbalance_ = mpdem::imbalance(*comm_, cost);
  ++measurements_;
  moved_ = imbalance_ > prm.balance_threshold && search_->shift_cuts(p, cost);
  if (moved_) {
    rebuild(p, b, true);  // the particles that changed brick migrate, with their history
    ++balances_;
  }
}

namespace {
// True when no element moves: every drive power is then 0 whatever the loads.
bool at_rest(const Barriers& b) {
  const auto still = [](const Vec3& v) { return v.x == 0.0 && v.y == 0.0 && v.z == 0.0; };
  return std::all_of(b.velocity.begin(), b.velocity.end(), still) && std::all_of(b.spin.begin(), b.spin.end(), still);
}

void set_loads(Barriers& b, std::span<const double> v) {
  for (std::size_t e = 0; e < b.size(); ++e) {
    for (int c = 0; c < 3; ++c) {
      b.force[e][c] = v[7 * e + static_cast<std::size_t>(c)];
      b.moment[e][c] = v[7 * e + 3 + static_cast<std::size_t>(c)];
    }
    b.pressure[e] = v[7 * e + 6];
  }
}
}  // namespace

std::vector<double> Interactions::barrier_loads(const Barriers& b) const {
  // One message: forces, moments, pressures.
  const std::size_t m = b.size();
  std::vector<double> v(7 * m);
  for (std::size_t e = 0; e < m; ++e) {
    for (int c = 0; c < 3; ++c) {
      v[7 * e + static_cast<std::size_t>(c)] = b.force[e][c];
      v[7 * e + 3 + static_cast<std::size_t>(c)] = b.moment[e][c];
    }
    v[7 * e + 6] = b.pressure[e];
  }
  return v;
}

void Interactions::reduce_barrier_loads(Barriers& b) {
  // The barriers are the same on every rank, so is this decision.
  loads_pending_ = defer_loads_ && at_rest(b);
  if (loads_pending_) return;
  std::vector<double> v = barrier_loads(b);
  comm_->sum(v);
  set_loads(b, v);
}

void Interactions::end_step_loads(Barriers& b, std::span<const double> summed) {
  if (loads_pending_) set_loads(b, summed);
  loads_pending_ = false;
  defer_loads_ = false;
}

InteractionStats Interactions::global_stats() const {
  if (!comm_) return stats_;
  // Summed over the ranks. drive_power and barrier_work come from the summed loads: already the
  // same on every rank.
  InteractionStats s = stats_;
  auto v = rank_summed_values(s);
  comm_->sum(v);
  set_rank_summed_values(s, v);
  return s;
}

}  // namespace mpdem
