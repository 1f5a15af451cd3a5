#include "neighbor/verlet_list.hpp"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/release.hpp"
#include "neighbor/csr_compaction.hpp"
#include "neighbor/csr_offsets.hpp"

namespace mpdem {

namespace {
// Insertion sort: a particle has a handful of neighbours, where std::sort's setup dominates; a
// large sphere among small ones has hundreds, where insertion sort would be quadratic.
void sort_row(std::uint32_t* first, std::uint32_t* last) {
  if (last - first > 32) {
    std::sort(first, last);
    return;
  }
  for (std::uint32_t* p = first + (first != last); p < last; ++p) {
    const std::uint32_t v = *p;
    std::uint32_t* q = p;
    for (; q > first && *(q - 1) > v; --q) *q = *(q - 1);
    *q = v;
  }
}

// Grows buf so that `more` entries fit after the first `used`, by a quarter at least: exact
// reservations keep the list's transient memory near its final size (resize alone doubles).
void reserve_row(std::vector<std::uint32_t>& buf, std::size_t used, std::size_t more) {
  if (buf.size() >= used + more) return;
  const std::size_t want = std::max(used + more, buf.size() + buf.size() / 4);
  if (want > buf.capacity()) buf.reserve(want);
  buf.resize(want);
}

// Fills the CSR rows of the owned particles [0, owned) of n: make() gives each thread its row
// finder, row(i, buf, used), which appends the neighbours j of row i to buf from position used.
// Each thread owns a contiguous block of rows: it writes only those counts and its own buffer,
// so the result is the same for any number of threads. Counts -> exclusive scan -> copy.
// Thread 0's rows come first: it writes them into `index` itself, which keeps its storage from
// the last build, so one thread needs no second copy of the list.
template <class MakeRow>
void fill_rows(std::size_t n, std::size_t owned, std::vector<std::uint32_t>& offset, std::vector<std::uint32_t>& index,
               MakeRow&& make) {
  offset.assign(n + 1, 0);
  bool too_many = false;                               // more than 2^32 - 1 pairs: beyond the 32-bit offsets
  std::vector<std::vector<std::uint32_t>> thread_buf;  // pair buffers of threads 1, 2, ...
  std::size_t share = 0;                               // expected entries per thread (last build)
#pragma omp parallel if (n >= kNeighborParallelMin)
  {
    const std::size_t nt = static_cast<std::size_t>(omp_get_num_threads());
    const std::size_t t = static_cast<std::size_t>(omp_get_thread_num());
#pragma omp single
    {
      thread_buf.resize(nt);
      share = index.size() / nt + index.size() / (8 * nt);
    }
    std::vector<std::uint32_t>& buf = t == 0 ? index : thread_buf[t];
    if (t > 0) buf.reserve(share);
    std::size_t used = 0;                                              // entries of buf in use
    const std::size_t lo = owned * t / nt, hi = owned * (t + 1) / nt;  // ghosts list no pairs
    auto row = make();
    for (std::size_t i = lo; i < hi; ++i) {
      const std::size_t first = used;
      row(i, buf, used);
      sort_row(buf.data() + first, buf.data() + used);
      offset[i + 1] = static_cast<std::uint32_t>(used - first);
    }
#pragma omp barrier
#pragma omp single
    {
      const std::optional<std::size_t> total = counts_to_offsets(offset);
      too_many = !total;
      if (total) {
        if (*total > index.capacity()) index.reserve(*total);  // exactly: resize alone may double
        index.resize(*total);                                  // keeps thread 0's rows at the front
      }
    }
    if (t > 0 && !too_many)
      std::copy(buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(used),
                index.begin() + static_cast<std::ptrdiff_t>(offset[lo]));
  }
  if (too_many) throw std::invalid_argument("neighbour list: more than 2^32 - 1 pairs for 32-bit offsets");
}

// One size level's particles binned in cells of their own side, in cell order.
struct LevelCells {
  CellGrid grid;
  double r_max = 0.0;                // m, the level's largest radius
  std::vector<std::uint32_t> index;  // [n_l] particle index, in cell order
  std::vector<Vec3> x;               // [n_l] m, centres in cell order
  std::vector<double> r;             // [n_l] m, radii in cell order
  std::vector<std::int64_t> id;      // [n_l] ids in cell order (with ghosts only)
};

// Rounding margin of a level's search box (relative): the box can only be wider than the ranges.
constexpr double kReachPad = 1.0 + 1e-9;
}  // namespace

void VerletList::build(std::span<const Vec3> x, std::span<const double> radius, double skin, double extra_range,
                       std::size_t owned, std::span<const std::int64_t> id, const std::function<void()>& after_pairs) {
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
  bool radii_ok = true, finite = true;
#pragma omp parallel for schedule(static) reduction(max : rmax) reduction(&& : radii_ok, finite) if (n >= kNeighborParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    radii_ok = radii_ok && radius[i] >= 0.0 && std::isfinite(radius[i]);
    finite = finite && isfinite(x[i]);
    rmax = std::max(rmax, radius[i]);
  }
  if (!radii_ok) throw std::invalid_argument("neighbour list: radii must be finite and >= 0");
  if (!finite) {  // named here: the size levels' grids see subsets, with their own indices
    for (std::size_t i = 0; i < n; ++i)
      if (!isfinite(x[i]))
        throw std::invalid_argument("neighbour search: particle at index " + std::to_string(i) +
                                    " has a non-finite position");
  }

  skin_ = skin;
  extra_ = extra_range;
  max_radius_ = rmax;
  const SizeLevels levels = size_levels(radius);
  if (levels.count() > 1) {
    build_levels(x, radius, levels, owned, id);
  } else {
    build_single(x, radius, owned, id);
  }
  owned_ = owned;
  if (after_pairs) after_pairs();
  x_build_.assign(x.begin(), x.end());
  built_ = true;
}

std::vector<std::uint32_t> VerletList::compact(const std::vector<char>& keep) {
  if (!built_ || x_build_.size() != owned_ || keep.size() != owned_)
    throw std::logic_error("VerletList::compact: not built, with ghosts, or keep does not match");
  const std::vector<std::uint32_t> to = kept_row_numbers(keep);
  std::vector<std::uint32_t> from;
  compact_rows(
      offset_, index_, keep, [&](std::uint32_t j) { return to[j]; }, &from);
  std::size_t n = 0;
  for (std::size_t i = 0; i < keep.size(); ++i)
    if (keep[i]) x_build_[n++] = x_build_[i];
  x_build_.resize(n);
  owned_ = n;
  return from;
}

void VerletList::drop_pairs_within_groups(std::span<const std::int64_t> group) {
  if (group.size() + 1 != offset_.size()) throw std::logic_error("VerletList: groups do not match the particles");
  std::uint32_t written = 0, begin = 0;
  for (std::size_t i = 0; i < group.size(); ++i) {
    const std::uint32_t end = offset_[i + 1];  // read before it is overwritten
    const std::int64_t g = group[i];
    for (std::uint32_t k = begin; k < end; ++k) {
      const std::uint32_t j = index_[k];
      if (g == kNoGroup || g != group[j]) index_[written++] = j;
    }
    offset_[i + 1] = written;
    begin = end;
  }
  index_.resize(written);
}

void VerletList::release_build_positions() {
  release(x_build_);
  built_ = false;
}

void VerletList::build_single(std::span<const Vec3> x, std::span<const double> radius, std::size_t owned,
                              std::span<const std::int64_t> id) {
  const std::size_t n = x.size();
  const bool ghosts = owned < n;
  const double extra_range = extra_, skin = skin_;
  // Any listed pair is closer than 2 R_max + extra + skin, so it lies in adjacent cells.
  CellGrid grid;
  grid.build(x, 2.0 * max_radius_ + extra_range + skin);
  grid_stats_ = {grid.num_cells(),    grid.hash_slots(),      grid.dense_slots(),
                 grid.memory_bytes(), grid.uses_morton_key(), grid.uses_dense_index()};

  // Centres and radii in cell order: the inner loop then streams contiguous memory.
  const auto sorted = grid.sorted();
  const auto start = grid.cell_start();
  std::vector<Vec3> xs(n);                        // m
  std::vector<double> rs(n);                      // m
  std::vector<std::int64_t> ids(ghosts ? n : 0);  // ids in cell order (with ghosts only)
#pragma omp parallel for schedule(static) if (n >= kNeighborParallelMin)
  for (std::size_t k = 0; k < n; ++k) {
    xs[k] = x[sorted[k]];
    rs[k] = radius[sorted[k]];
    if (ghosts) ids[k] = id[sorted[k]];
  }

  fill_rows(n, owned, offset_, index_, [&] {
    return [&, cell_buf = std::array<std::uint32_t, 27>{}, ncells = 0,
            last_cell = CellGrid::kNone](std::size_t i, std::vector<std::uint32_t>& buf, std::size_t& used) mutable {
      const Vec3 xi = x[i];
      const double ri = radius[i];
      const std::uint32_t cell = grid.cell_of(i);
      if (cell != last_cell) {  // particles come in space-filling-curve order: cells repeat
        ncells = grid.neighbor_cells(cell, cell_buf.data());
        last_cell = cell;
      }
      const std::span<const std::uint32_t> cells(cell_buf.data(), static_cast<std::size_t>(ncells));
      std::size_t candidates = 0;
      for (std::uint32_t nc : cells) candidates += start[nc + 1] - start[nc];
      reserve_row(buf, used, candidates);
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
    };
  });
}

void VerletList::build_levels(std::span<const Vec3> x, std::span<const double> radius, const SizeLevels& levels,
                              std::size_t owned, std::span<const std::int64_t> id) {
  const std::size_t n = x.size();
  const bool ghosts = owned < n;
  const double extra_range = extra_, skin = skin_;
  // Each level in cells of side 2 R_max(level) + extra + skin, its particles in cell order.
  std::vector<LevelCells> cells(levels.count());
  std::vector<std::vector<std::uint32_t>> members(levels.count());
  for (std::size_t i = 0; i < n; ++i) members[levels.level[i]].push_back(static_cast<std::uint32_t>(i));
  grid_stats_ = {};
  for (std::size_t l = 0; l < cells.size(); ++l) {
    LevelCells& c = cells[l];
    const std::vector<std::uint32_t>& m = members[l];
    const std::size_t nl = m.size();
    if (nl == 0) continue;
    c.r_max = levels.r_max[l];
    std::vector<Vec3> xl(nl);
    Vec3 lo = x[m[0]], hi = x[m[0]];  // m, the level's bounding box
    for (std::size_t k = 0; k < nl; ++k) {
      xl[k] = x[m[k]];
      lo = {std::min(lo.x, xl[k].x), std::min(lo.y, xl[k].y), std::min(lo.z, xl[k].z)};
      hi = {std::max(hi.x, xl[k].x), std::max(hi.y, xl[k].y), std::max(hi.z, xl[k].z)};
    }
    // A sparse level (a few small spheres among large ones) gets cells of about one particle each,
    // so that a large sphere's search box on it spans a few cells rather than thousands of empty
    // ones; a wider cell only adds candidates, never loses a pair.
    const double side = 2.0 * c.r_max + extra_range + skin;
    const double volume = (hi.x - lo.x + side) * (hi.y - lo.y + side) * (hi.z - lo.z + side);  // m^3
    c.grid.build(xl, std::max(side, std::cbrt(volume / static_cast<double>(nl))));
    c.index.resize(nl);
    c.x.resize(nl);
    c.r.resize(nl);
    c.id.resize(ghosts ? nl : 0);
    const auto sorted = c.grid.sorted();
    for (std::size_t k = 0; k < nl; ++k) {
      const std::uint32_t i = m[sorted[k]];
      c.index[k] = i;
      c.x[k] = x[i];
      c.r[k] = radius[i];
      if (ghosts) c.id[k] = id[i];
    }
    grid_stats_.cells += c.grid.num_cells();
    grid_stats_.hash_slots += c.grid.hash_slots();
    grid_stats_.dense_slots += c.grid.dense_slots();
    grid_stats_.bytes += c.grid.memory_bytes();
  }
  release(members);
  grid_stats_.morton_key = grid_stats_.dense_index = true;
  for (const LevelCells& c : cells) {
    if (c.index.empty()) continue;
    grid_stats_.morton_key = grid_stats_.morton_key && c.grid.uses_morton_key();
    grid_stats_.dense_index = grid_stats_.dense_index && c.grid.uses_dense_index();
  }
  grid_stats_.levels = cells.size();

  // Row i searches every level over the cells its largest pair range with that level can reach.
  fill_rows(n, owned, offset_, index_, [&] {
    return [&](std::size_t i, std::vector<std::uint32_t>& buf, std::size_t& used) {
      const Vec3 xi = x[i];
      const double ri = radius[i];
      const std::int64_t idi = ghosts ? id[i] : 0;
      for (const LevelCells& level : cells) {
        if (level.index.empty()) continue;
        const CellGrid& g = level.grid;
        const double reach = (ri + level.r_max + extra_range + skin) * kReachPad;
        const Vec3 span{reach, reach, reach};
        CellCoord lo = g.coord_of(xi - span), hi = g.coord_of(xi + span);
        lo = {std::max<std::int64_t>(lo.x, 0), std::max<std::int64_t>(lo.y, 0), std::max<std::int64_t>(lo.z, 0)};
        hi = {std::min(hi.x, g.dim(0) - 1), std::min(hi.y, g.dim(1) - 1), std::min(hi.z, g.dim(2) - 1)};
        const auto start = g.cell_start();
        for (std::int64_t cz = lo.z; cz <= hi.z; ++cz)
          for (std::int64_t cy = lo.y; cy <= hi.y; ++cy)
            for (std::int64_t cx = lo.x; cx <= hi.x; ++cx) {
              const std::uint32_t c = g.find({cx, cy, cz});
              if (c == CellGrid::kNone) continue;
              reserve_row(buf, used, start[c + 1] - start[c]);
              std::uint32_t* out = buf.data();
              for (std::uint32_t k = start[c]; k < start[c + 1]; ++k) {
                const std::uint32_t j = level.index[k];
                const Vec3 d = level.x[k] - xi;
                const double cut = ri + level.r[k] + extra_range + skin;  // the same criterion
                const bool second = j < owned ? j > i : idi < level.id[k];
                out[used] = j;
                used += static_cast<std::size_t>(second & (norm2(d) < cut * cut));
              }
            }
      }
    };
  });
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
  const double limit2 = half_skin2();
  bool exceeded = false;
  const std::size_t n = owned_;
#pragma omp parallel for schedule(static) reduction(|| : exceeded) if (n >= kNeighborParallelMin)
  for (std::size_t i = 0; i < n; ++i) exceeded = exceeded || norm2(x[i] - x_build_[i]) > limit2;
  return exceeded;
}

std::size_t VerletList::memory_bytes() const {
  return x_build_.capacity() * sizeof(Vec3) + offset_.capacity() * sizeof(std::uint32_t) +
         index_.capacity() * sizeof(std::uint32_t);
}

}  // namespace mpdem
