#pragma once
// Load balance of a brick decomposition (docs/parallel.md, "Load balance"): the cut planes of a
// BrickGrid move along each decomposed axis so that the slabs between them carry equal cost, in
// the manner of LAMMPS's `balance shift`. The cost is measured per rank (its evaluation time, or
// a deterministic count) and spread over its particles; the histogram of that cost along an
// axis, summed over the ranks, places each cut at its quantile.
#include <span>

#include "core/vec3.hpp"
#include "parallel/brick_grid.hpp"
#include "parallel/communicator.hpp"

namespace mpdem {

// max / mean of the ranks' costs (1 = balanced; 1 when every cost is 0). Collective.
double imbalance(const Communicator& comm, double cost);

// Moves the interior cuts of `grid` along every decomposed axis towards the quantiles of the
// cost along it: `cost` (any unit, >= 0) is this rank's, spread evenly over its particles at
// `x` (m, the owned centres). Each new cut stays strictly between its two old neighbours (a
// particle then changes owner by at most one brick per axis: a migration's reach), and every
// bounded brick keeps at least `min_width` (m; the halo's reach). An axis where no placement
// satisfies both keeps its cuts. Returns true when a cut moved; the same grid on every rank.
// Collective.
bool shift_cuts(BrickGrid& grid, const Communicator& comm, std::span<const Vec3> x, double cost, double min_width);

}  // namespace mpdem
