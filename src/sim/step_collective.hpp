#pragma once
// StepCollective: what the checks after a step read over all ranks (docs/parallel.md) - the
// interaction statistics, the particle count, the health scan, the deepest overlap - with the
// stop signal, rank 0's particle snapshot decision and the barrier loads when they wait for it
// (Interactions::barrier_loads_pending), combined in one collective: each
// collective makes every rank wait for the slowest, so a step pays for one rather than six.
// Sums are taken element by element in rank order, as Communicator::sum takes them: the bits of
// separate reductions, on every rank.
#include <cstdint>
#include <vector>

#include "contact/particle_contacts.hpp"
#include "interact/interactions.hpp"
#include "integrate/health_scan.hpp"

namespace mpdem {

class Communicator;

struct StepCollective {
  InteractionStats stats;       // the rows summed over the ranks (interaction_stats.hpp) summed; the rest as given
  std::uint64_t particles = 0;  // owned particles, summed
  HealthScan scan;              // summed
  OverlapReport deepest;        // the deepest overlap; rank: the rank that holds it (the lowest on a tie)
  int stop = 0;                 // the stop signal received (0: none), the largest of the ranks'
  // The particle snapshots due after the step (OutputManager::particles_due): rank 0's decision.
  bool vtu = false, csv = false, body_csv = false, bonds = false;
  std::uint64_t vtu_index = 0;
  // Barrier loads still to be summed (Interactions::barrier_loads_pending), 7 per element: summed
  // (the same count on every rank); empty when none.
  std::vector<double> loads;
  std::uint64_t bond_breaks = 0;  // the bonds' breaks not yet collected (Bonds::breaks), summed
};

// Every rank's totals combined, the same on every rank. Collective.
StepCollective combine_over_ranks(const Communicator& comm, const StepCollective& mine);

}  // namespace mpdem
