// Interactions' part in an open system (sim/simulation_open_system.cpp): particles removed and
// added between steps, their contact history kept, and whether a removal changes the others' rates.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <type_traits>
#include <utility>
#include <vector>

#include "contact/barrier_contacts.hpp"
#include "contact/bonds.hpp"
#include "contact/pair_batch.hpp"
#include "contact/particle_contacts.hpp"
#include "field/near_field_forces.hpp"
#include "neighbor/neighbor_search.hpp"
#include "parallel/gather.hpp"
#include "interact/interactions.hpp"
#include "thermal/heat_transfer.hpp"

namespace mpdem {

bool Interactions::removal_acts_on_others(const Particles& p, const std::vector<char>& keep) const {
  // Anything but contacts and per-particle field forces (a near field, heat flows and their
  // outward totals, added loads, the contact records of the contact output) is left to the
  // re-evaluation.
  bool acts = near_ || heat_ || !external_.empty() || particle_contacts_->recording() || search_->stale(p);
  const std::size_t n = p.size(), all = p.size_with_ghosts();
  if (!acts && p.any_fixed())  // a held particle's power (fixed_power)
    for (std::size_t i = 0; i < n && !acts; ++i) acts = keep[i] == 0 && p.fixed[i] != 0;
  // The removed particles by id, on every rank: a ghost (a periodic image, another rank's
  // particle) carries its source's id, and its pairs may be listed on a rank that does not own it.
  std::vector<std::int64_t> ids;
  for (std::size_t i = 0; i < n; ++i)
    if (keep[i] == 0) ids.push_back(p.id[i]);
  if (comm_) ids = all_gather_values<std::int64_t>(*comm_, ids);
  std::sort(ids.begin(), ids.end());
  std::vector<char> gone(all, 0);
  for (std::size_t i = 0; i < all; ++i)
    gone[i] = static_cast<char>(i < n ? keep[i] == 0 : std::binary_search(ids.begin(), ids.end(), p.id[i]));
  // A listed pair with a removed member within the pair kernel's candidate reach (a superset of
  // the touching pairs), at the positions of the last evaluation.
  if (!acts) {
    const auto& idx = search_->pairs().indices();
    const auto& first = search_->blocks().first_members();
    for (std::size_t k = 0; k < idx.size() && !acts; ++k) {
      const std::uint32_t i = first[k], j = idx[k];
      if (!gone[i] && !gone[j]) continue;
      const double reach = p.radius[i] + p.radius[j];
      acts = norm2(p.x[i] - p.x[j]) <= reach * reach * kCandidateReach;
    }
  }
  // A barrier contact of a removed particle (made on its owner) at the last, committed,
  // evaluation: its load. (The store's layout is the last evaluation's unless there are no
  // barriers, and so no contacts.)
  const BarrierContactStore& store = barrier_contacts_->store();
  const bool barriers = search_->barrier_candidates().num_elements() > 0;
  if (!acts && barriers && store.stale(search_->barrier_candidates())) acts = true;
  for (std::size_t k = 0; barriers && k < store.size() && !acts; ++k)
    acts = store.particle(k) < n && gone[store.particle(k)] && store.load_used(k) > 0;
  return any_rank(acts);
}

void Interactions::remove_particles(Particles& p, const Barriers& b, const std::vector<char>& keep) {
  next_drift_.valid = false;
  if (bonds_) {
    // Their bonds go with them (on several ranks a bond may live on another rank than its particle).
    std::vector<std::int64_t> gone;
    for (std::size_t i = 0; i < keep.size(); ++i)
      if (!keep[i]) gone.push_back(p.id[i]);
    if (comm_) gone = all_gather_values<std::int64_t>(*comm_, gone);
    bonds_->remove_particles(gone);
  }
  if (comm_) {
    // Collective (the lists are rebuilt on every rank); the ghosts' sources are remote: by ids.
    std::vector<PairHistory> kept = particle_contacts_->export_history(p, *search_);
    p.drop_ghosts();
    p.compact(keep);
    barrier_contacts_->compact(keep);
    search_->rebuild(p, b);
    particle_contacts_->import_history(p, *search_, std::move(kept));
    stats_.rebuilds = search_->rebuilds();
    return;
  }
  if (search_->compactable(p)) {
    // The lists stay valid for the others: compacted, no search (a discharge removes particles
    // at many steps between its rebuilds).
    const std::size_t old_pairs = search_->pairs().num_pairs();
    particle_contacts_->compact_slots(search_->compact(keep), old_pairs);
    p.compact(keep);
    barrier_contacts_->compact(keep);
    return;
  }
  ParticleContacts::CarriedHistory history = particle_contacts_->carry_history(*search_);
  p.drop_ghosts();
  std::vector<std::uint32_t> old_index;  // old index of each particle kept
  for (std::size_t i = 0; i < keep.size(); ++i)
    if (keep[i]) old_index.push_back(static_cast<std::uint32_t>(i));
  p.compact(keep);
  barrier_contacts_->compact(keep);
  search_->rebuild(p, b);
  particle_contacts_->restore_history(*search_, std::move(history), old_index);
  stats_.rebuilds = search_->rebuilds();
}

void Interactions::add_particles(Particles& p, const Barriers& b, Particles fresh) {
  next_drift_.valid = false;
  // Each array of `fresh` onto the end of p's: both lists name the arrays in the same order.
  const auto append = [&] {
    std::size_t k = 0;
    p.for_each_array([&](const char*, auto& to) {
      std::size_t j = 0;
      fresh.for_each_array([&](const char*, auto& from) {
        if constexpr (std::is_same_v<decltype(to), decltype(from)>)
          if (j == k) to.insert(to.end(), from.begin(), from.end());
        ++j;
      });
      ++k;
    });
    // New clump bodies (an inlet's) after the present ones; their members name them by id.
    if (!fresh.bodies.empty()) {
      k = 0;
      p.bodies.for_each_array([&](const char*, auto& to) {
        std::size_t j = 0;
        fresh.bodies.for_each_array([&](const char*, auto& from) {
          if constexpr (std::is_same_v<decltype(to), decltype(from)>)
            if (j == k) to.insert(to.end(), from.begin(), from.end());
          ++j;
        });
        ++k;
      });
    }
    p.bodies.stale = true;
  };
  if (comm_) {
    // Collective, as remove_particles: the ghosts' sources are remote, so the history goes by ids.
    std::vector<PairHistory> kept = particle_contacts_->export_history(p, *search_);
    p.drop_ghosts();
    append();
    search_->rebuild(p, b);
    particle_contacts_->import_history(p, *search_, std::move(kept));
    stats_.rebuilds = search_->rebuilds();
    return;
  }
  ParticleContacts::CarriedHistory history = particle_contacts_->carry_history(*search_);
  p.drop_ghosts();
  const std::size_t old_n = p.size();
  append();
  // The others keep their indices (and so their barrier contact records); a new particle has
  // no old index (beyond any old list, ghosts included: no carried pair is found for it).
  std::vector<std::uint32_t> old_index(p.size(), std::numeric_limits<std::uint32_t>::max());
  std::iota(old_index.begin(), old_index.begin() + static_cast<std::ptrdiff_t>(old_n), std::uint32_t{0});
  search_->rebuild(p, b);
  particle_contacts_->restore_history(*search_, std::move(history), old_index);
  stats_.rebuilds = search_->rebuilds();
}

}  // namespace mpdem
