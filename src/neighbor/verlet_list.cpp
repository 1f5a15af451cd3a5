#include "neighbor/verlet_list.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace mpdem {

namespace {
// Insertion sort: a particle has a handful of neighbours, where std::sort's setup dominates.
void sort_short(std::uint32_t* first, std::uint32_t* last) {
  for (std::uint32_t* p = first + (first != last); p < last; ++p) {
    const std::uint32_t v = *p;
    std::uint32_t* q = p;
    for (; q > first && *(q - 1) > v; --q) *q = *(q - 1);
    *q = v;
  }
}
}  // namespace

void VerletList::build(std::span<const Vec3> x, std::span<const double> radius, double skin, double extra_range,
                       std::size_t owned, std::span<const std::int64_t> id) {
  const std::size_t n = x.size();
  if (radius.size() != n) throw std::invalid_argument("neighbour list: positions and radii differ in size");
  const bool ghosts = owned < n;
  if (owned > n || (ghosts && id.size() != n))
    throw std::invalid_argument("neighbour list: ghosts need the ids of all particles");
  if (!(skin >= 0.0) || !std::isfinite(skin)) throw std::invalid_argument("neighbour list: skin must be >= 0");
  if (!(extra_range >= 0.0) || !std::isfinite(extra_range))
    throw std::invalid_argument("neighbour list: extra range must be >= 0");
  if (n >= std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument("neighbour list: too many particles for 32-bit indices");

  double rmax = 0.0;
  bool radii_ok = true;
#pragma omp parallel for schedule(static) reduction(max : rmax) reduction(&& : radii_ok) if (n >= kNeighborParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    radii_ok = radii_ok && radius[i] >= 0.0 && std::isfinite(radius[i]);
    rmax = std::max(rmax, radius[i]);
  }
  if (!radii_ok) throw std::invalid_argument("neighbour list: radii must be finite and >= 0");

  skin_ = skin;
  extra_ = extra_range;
  max_radius_ = rmax;
  // Any listed pair is closer than 2 R_max + extra + skin, so it lies in adjacent cells.
  CellGrid grid;
  grid.build(x, 2.0 * rmax + extra_range + skin);
  grid_stats_ = {grid.num_cells(),    grid.hash_slots(),      grid.dense_slots(),
                 grid.memory_bytes(), grid.uses_morton_key(), grid.uses_dense_index()};

  // Centres and radii in cell order: the inner loop then streams contiguous memory.
  const auto sorted = grid.sorted();
  const auto start = grid.cell_start();
  std::vector<Vec3> xs(n);                             // m
  std::vector<double> rs(n);                           // m
  std::vector<std::int64_t> ids(ghosts ? n : 0);       // ids in cell order (with ghosts only)
  std::vector<std::vector<std::uint32_t>> thread_buf;  // per-thread pair buffers
#pragma omp parallel for schedule(static) if (n >= kNeighborParallelMin)
  for (std::size_t k = 0; k < n; ++k) {
    xs[k] = x[sorted[k]];
    rs[k] = radius[sorted[k]];
    if (ghosts) ids[k] = id[sorted[k]];
  }
  x_build_.assign(x.begin(), x.end());
  owned_ = owned;
  offset_.assign(n + 1, 0);

  // Each thread owns a contiguous block of i: it writes only those counts and its own buffer,
  // so the result is the same for any number of threads. Counts -> exclusive scan -> copy.
#pragma omp parallel if (n >= kNeighborParallelMin)
  {
    const std::size_t nt = static_cast<std::size_t>(omp_get_num_threads());
    const std::size_t t = static_cast<std::size_t>(omp_get_thread_num());
#pragma omp single
    thread_buf.resize(nt);
    std::vector<std::uint32_t>& buf = thread_buf[t];
    std::size_t used = 0;                                              // entries of buf in use
    const std::size_t lo = owned * t / nt, hi = owned * (t + 1) / nt;  // ghosts list no pairs
    std::uint32_t cell_buf[27];
    int ncells = 0;
    std::uint32_t last_cell = CellGrid::kNone;
    for (std::size_t i = lo; i < hi; ++i) {
      const std::size_t first = used;
      const Vec3 xi = x[i];
      const double ri = radius[i];
      const std::uint32_t cell = grid.cell_of(i);
      if (cell != last_cell) {  // particles come in space-filling-curve order: cells repeat
        ncells = grid.neighbor_cells(cell, cell_buf);
        last_cell = cell;
      }
      const std::span<const std::uint32_t> cells(cell_buf, static_cast<std::size_t>(ncells));
      std::size_t candidates = 0;
      for (std::uint32_t nc : cells) candidates += start[nc + 1] - start[nc];
      if (buf.size() < used + candidates) buf.resize(std::max(2 * buf.size(), used + candidates));
      std::uint32_t* out = buf.data();
      // Branch-free filter: every candidate is written, the slot is kept only on a hit (the
      // j > i and distance tests are data-dependent coin flips a branch predictor loses).
      if (!ghosts) {
        for (std::uint32_t nc : cells) {
          for (std::uint32_t k = start[nc]; k < start[nc + 1]; ++k) {
            const std::uint32_t j = sorted[k];
            const Vec3 d = xs[k] - xi;
            const double cut = ri + rs[k] + extra_range + skin;  // documented pair criterion
            out[used] = j;
            used += static_cast<std::size_t>((j > i) & (norm2(d) < cut * cut));
          }
        }
      } else {
        const std::int64_t idi = id[i];
        for (std::uint32_t nc : cells) {
          for (std::uint32_t k = start[nc]; k < start[nc + 1]; ++k) {
            const std::uint32_t j = sorted[k];
            const Vec3 d = xs[k] - xi;
            const double cut = ri + rs[k] + extra_range + skin;
            const bool second = j < owned ? j > i : idi < ids[k];  // ghosts: one image of the pair
            out[used] = j;
            used += static_cast<std::size_t>(second & (norm2(d) < cut * cut));
          }
        }
      }
      sort_short(out + first, out + used);
      offset_[i + 1] = used - first;
    }
#pragma omp barrier
#pragma omp single
    {
      for (std::size_t i = 0; i < n; ++i) offset_[i + 1] += offset_[i];
      index_.resize(offset_[n]);
    }
    std::copy(buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(used),
              index_.begin() + static_cast<std::ptrdiff_t>(offset_[lo]));
  }
  built_ = true;
}

double VerletList::max_displacement(std::span<const Vec3> x) const {
  if (!built_ || (x.size() != x_build_.size() && x.size() != owned_)) return std::numeric_limits<double>::infinity();
  double m2 = 0.0;
  const std::size_t n = owned_;
#pragma omp parallel for schedule(static) reduction(max : m2) if (n >= kNeighborParallelMin)
  for (std::size_t i = 0; i < n; ++i) m2 = std::max(m2, norm2(x[i] - x_build_[i]));
  return std::sqrt(m2);
}

bool VerletList::needs_rebuild(std::span<const Vec3> x) const {
  // Compared squared so the threshold is exact: rebuild iff some |dx_i|^2 > (skin/2)^2.
  if (!built_ || (x.size() != x_build_.size() && x.size() != owned_)) return true;
  const double half = 0.5 * skin_;
  const double limit2 = half * half;
  bool exceeded = false;
  const std::size_t n = owned_;
#pragma omp parallel for schedule(static) reduction(|| : exceeded) if (n >= kNeighborParallelMin)
  for (std::size_t i = 0; i < n; ++i) exceeded = exceeded || norm2(x[i] - x_build_[i]) > limit2;
  return exceeded;
}

std::size_t VerletList::memory_bytes() const {
  return x_build_.capacity() * sizeof(Vec3) + offset_.capacity() * sizeof(std::size_t) +
         index_.capacity() * sizeof(std::uint32_t);
}

}  // namespace mpdem
