#include "neighbor/cell_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/release.hpp"

namespace mpdem {

namespace {

// Largest cell count per axis. Cell coordinates below 2^30 are computed with an error far below
// 1e-6 cell, which the 1e-6 enlargement of the side absorbs: two points closer than the
// requested side always land in the same or adjacent cells.
constexpr double kMaxCellsPerAxis = 1073741824.0;  // 2^30
constexpr double kSidePad = 1.0 + 1e-6;
constexpr std::int64_t kMortonLimit = std::int64_t{1} << 21;  // 21 bits per axis fit 63 bits

// Spreads the low 21 bits of v so bit k moves to bit 3k.
std::uint64_t spread3(std::uint64_t v) {
  v &= 0x1FFFFFull;
  v = (v | (v << 32)) & 0x1F00000000FFFFull;
  v = (v | (v << 16)) & 0x1F0000FF0000FFull;
  v = (v | (v << 8)) & 0x100F00F00F00F00Full;
  v = (v | (v << 4)) & 0x10C30C30C30C30C3ull;
  v = (v | (v << 2)) & 0x1249249249249249ull;
  return v;
}

// Inverse of spread3: gathers bits 0, 3, 6, ... of v into the low 21 bits.
std::uint64_t compact3(std::uint64_t v) {
  v &= 0x1249249249249249ull;
  v = (v | (v >> 2)) & 0x10C30C30C30C30C3ull;
  v = (v | (v >> 4)) & 0x100F00F00F00F00Full;
  v = (v | (v >> 8)) & 0x1F0000FF0000FFull;
  v = (v | (v >> 16)) & 0x1F00000000FFFFull;
  v = (v | (v >> 32)) & 0x1FFFFFull;
  return v;
}

// True when the most significant set bit of a is below that of b.
bool msb_less(std::uint64_t a, std::uint64_t b) { return a < b && a < (a ^ b); }

// splitmix64 finaliser: a well-mixed 64-bit hash of the three coordinates.
std::uint64_t mix(const CellCoord& c) {
  std::uint64_t h = static_cast<std::uint64_t>(c.x) * 0x9E3779B97F4A7C15ull;
  h ^= static_cast<std::uint64_t>(c.y) * 0xC2B2AE3D27D4EB4Full;
  h ^= static_cast<std::uint64_t>(c.z) * 0x165667B19E3779F9ull;
  h ^= h >> 30;
  h *= 0xBF58476D1CE4E5B9ull;
  h ^= h >> 27;
  h *= 0x94D049BB133111EBull;
  h ^= h >> 31;
  return h;
}

// floor(u) as a cell coordinate, clamped so a far query point cannot overflow the cast.
std::int64_t cell_index(double u) {
  constexpr double kClamp = 4.0e18;
  return static_cast<std::int64_t>(std::floor(std::clamp(u, -kClamp, kClamp)));
}

}  // namespace

std::uint64_t morton_key(const CellCoord& c) {
  return spread3(static_cast<std::uint64_t>(c.x)) | (spread3(static_cast<std::uint64_t>(c.y)) << 1) |
         (spread3(static_cast<std::uint64_t>(c.z)) << 2);
}

bool morton_less(const CellCoord& a, const CellCoord& b) {
  const std::uint64_t ax[3] = {static_cast<std::uint64_t>(a.z), static_cast<std::uint64_t>(a.y),
                               static_cast<std::uint64_t>(a.x)};
  const std::uint64_t bx[3] = {static_cast<std::uint64_t>(b.z), static_cast<std::uint64_t>(b.y),
                               static_cast<std::uint64_t>(b.x)};
  int d = 0;
  std::uint64_t best = ax[0] ^ bx[0];
  for (int k = 1; k < 3; ++k) {
    const std::uint64_t diff = ax[k] ^ bx[k];
    if (msb_less(best, diff)) {
      d = k;
      best = diff;
    }
  }
  return ax[d] < bx[d];
}

CellCoord CellGrid::coord_of(const Vec3& p) const {
  return {cell_index((p.x - origin_.x) * inv_side_), cell_index((p.y - origin_.y) * inv_side_),
          cell_index((p.z - origin_.z) * inv_side_)};
}

std::size_t CellGrid::slot_of(const CellCoord& c) const { return mix(c) & (table_.size() - 1); }

std::uint32_t CellGrid::find(const CellCoord& c) const {
  if (!dense_.empty()) {
    if (c.x < 0 || c.y < 0 || c.z < 0 || c.x >= dims_[0] || c.y >= dims_[1] || c.z >= dims_[2]) return kNone;
    return dense_[static_cast<std::size_t>((c.z * dims_[1] + c.y) * dims_[0] + c.x)];
  }
  if (table_.empty()) return kNone;
  const std::size_t mask = table_.size() - 1;
  for (std::size_t s = slot_of(c);; s = (s + 1) & mask) {
    const std::uint32_t cell = table_[s];
    if (cell == kNone) return kNone;
    if (coord_[cell] == c) return cell;
  }
}

void CellGrid::build(std::span<const Vec3> x, double cell_side, bool find_neighbors) {
  const std::size_t n = x.size();
  // Bounding box of the centres (min/max are exact, so the reduction is thread-independent).
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  bool finite = true;
#pragma omp parallel for schedule(static) reduction(min : lo[:3]) reduction(max : hi[:3]) reduction(&& : finite) if(n >= kNeighborParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    finite = finite && isfinite(x[i]);
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], x[i][a]);
      hi[a] = std::max(hi[a], x[i][a]);
    }
  }
  if (!finite) {
    for (std::size_t i = 0; i < n; ++i)
      if (!isfinite(x[i]))
        throw std::invalid_argument("neighbour search: particle at index " + std::to_string(i) +
                                    " has a non-finite position");
  }
  double extent = 0.0;
  if (n > 0) {
    origin_ = {lo[0], lo[1], lo[2]};
    extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  } else {
    origin_ = {};
  }
  side_ = std::max(cell_side > 0.0 && std::isfinite(cell_side) ? cell_side : 1.0, extent / kMaxCellsPerAxis) * kSidePad;
  if (!(side_ > 0.0)) side_ = 1.0;  // extent 0 and a tiny side underflowing cannot happen, but be safe
  inv_side_ = 1.0 / side_;

  // Cell coordinates of every particle; the Morton key fits 63 bits when every axis has < 2^21
  // cells, else the (slower) bitwise Z-order comparison gives the same order.
  pcoord_.resize(n);
  std::int64_t mx = 0, my = 0, mz = 0;
#pragma omp parallel for schedule(static) reduction(max : mx, my, mz) if (n >= kNeighborParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    pcoord_[i] = coord_of(x[i]);
    mx = std::max(mx, pcoord_[i].x);
    my = std::max(my, pcoord_[i].y);
    mz = std::max(mz, pcoord_[i].z);
  }
  dims_[0] = mx + 1;
  dims_[1] = my + 1;
  dims_[2] = mz + 1;
  morton_fast_ = std::max({mx, my, mz}) < kMortonLimit;
  sort_particles(n);
  index_cells(find_neighbors);
  // Sort scratch and per-particle coordinates are not needed after the build (peak memory).
  release(pcoord_);
  release(keys_);
  release(keys_tmp_);
}

void CellGrid::sort_particles(std::size_t n) {
  sorted_.resize(n);
  if (!morton_fast_) {
    // Rare path (> 2^21 cells along an axis): comparison sort, ties by index.
    for (std::size_t i = 0; i < n; ++i) sorted_[i] = static_cast<std::uint32_t>(i);
    std::sort(sorted_.begin(), sorted_.end(), [this](std::uint32_t a, std::uint32_t b) {
      const CellCoord& ca = pcoord_[a];
      const CellCoord& cb = pcoord_[b];
      if (ca == cb) return a < b;
      return morton_less(ca, cb);
    });
    keys_.clear();
    keys_tmp_.clear();
    return;
  }
  keys_.resize(n);
  keys_tmp_.resize(n);
#pragma omp parallel for schedule(static) if (n >= kNeighborParallelMin)
  for (std::size_t i = 0; i < n; ++i) keys_[i] = {morton_key(pcoord_[i]), static_cast<std::uint32_t>(i)};
  // LSD radix sort, 11 bits per pass, only over the bits the keys use. Stable, and the input is
  // in index order, so equal keys stay ordered by index: the order is (key, index).
  std::int64_t span = std::max({dims_[0], dims_[1], dims_[2]}) - 1;
  int bits_per_axis = 0;
  while (span > 0) {
    ++bits_per_axis;
    span >>= 1;
  }
  const int key_bits = 3 * bits_per_axis;
  constexpr int kDigit = 11;
  constexpr std::size_t kBuckets = std::size_t{1} << kDigit;
  std::vector<std::size_t> count(kBuckets);
  for (int shift = 0; shift < key_bits; shift += kDigit) {
    std::fill(count.begin(), count.end(), 0);
    for (std::size_t i = 0; i < n; ++i) ++count[(keys_[i].key >> shift) & (kBuckets - 1)];
    std::size_t sum = 0;
    for (auto& c : count) {
      const std::size_t k = c;
      c = sum;
      sum += k;
    }
    for (std::size_t i = 0; i < n; ++i) keys_tmp_[count[(keys_[i].key >> shift) & (kBuckets - 1)]++] = keys_[i];
    keys_.swap(keys_tmp_);
  }
#pragma omp parallel for schedule(static) if (n >= kNeighborParallelMin)
  for (std::size_t k = 0; k < n; ++k) sorted_[k] = keys_[k].index;
}

void CellGrid::index_cells(bool find_neighbors) {
  const std::size_t n = sorted_.size();
  // Runs of equal coordinates are the occupied cells.
  cell_of_.resize(n);
  coord_.clear();
  start_.clear();
  for (std::size_t k = 0; k < n; ++k) {
    // On the key path the coordinates are decoded from the (sequential) keys rather than
    // gathered from pcoord_ in random order.
    const bool new_cell = k == 0 ||
                          (morton_fast_ ? keys_[k].key != keys_[k - 1].key : !(pcoord_[sorted_[k]] == coord_.back()));
    if (new_cell) {
      if (morton_fast_) {
        const std::uint64_t key = keys_[k].key;
        coord_.push_back({static_cast<std::int64_t>(compact3(key)), static_cast<std::int64_t>(compact3(key >> 1)),
                          static_cast<std::int64_t>(compact3(key >> 2))});
      } else {
        coord_.push_back(pcoord_[sorted_[k]]);
      }
      start_.push_back(static_cast<std::uint32_t>(k));
    }
    cell_of_[sorted_[k]] = static_cast<std::uint32_t>(coord_.size() - 1);
  }
  start_.push_back(static_cast<std::uint32_t>(n));
  const std::size_t ncell = coord_.size();

  // Compact sets: a dense array over the bounding box (direct, cache-friendly lookups), allowed
  // only while it stays within kDenseFactor N slots. Otherwise a hash table at most half full.
  const double box_cells = static_cast<double>(dims_[0]) * static_cast<double>(dims_[1]) *
                           static_cast<double>(dims_[2]);
  table_.clear();
  dense_.clear();
  if (!find_neighbors) return;
  if (n > 0 && box_cells <= kDenseFactor * static_cast<double>(n)) {
    dense_.assign(static_cast<std::size_t>(box_cells), kNone);
    for (std::size_t c = 0; c < ncell; ++c) {
      const CellCoord& cc = coord_[c];
      dense_[static_cast<std::size_t>((cc.z * dims_[1] + cc.y) * dims_[0] + cc.x)] = static_cast<std::uint32_t>(c);
    }
  } else {
    std::size_t slots = 16;
    while (slots < 2 * ncell) slots *= 2;
    table_.assign(slots, kNone);
    for (std::size_t c = 0; c < ncell; ++c) {
      std::size_t s = slot_of(coord_[c]);
      while (table_[s] != kNone) s = (s + 1) & (slots - 1);
      table_[s] = static_cast<std::uint32_t>(c);
    }
  }

  for (int k = 0; k < 27; ++k) dense_offset_[k] = ((k / 9 - 1) * dims_[1] + (k / 3 % 3 - 1)) * dims_[0] + (k % 3 - 1);
}

int CellGrid::neighbor_cells(std::size_t c, std::uint32_t out[27]) const {
  // Interior cells of the dense index need no bounds checks: fixed slot offsets.
  int count = 0;
  const CellCoord& cc = coord_[c];
  const bool interior = !dense_.empty() && cc.x > 0 && cc.y > 0 && cc.z > 0 && cc.x + 1 < dims_[0] &&
                        cc.y + 1 < dims_[1] && cc.z + 1 < dims_[2];
  if (interior) {
    const std::int64_t base = (cc.z * dims_[1] + cc.y) * dims_[0] + cc.x;
    for (int k = 0; k < 27; ++k) {
      const std::uint32_t f = dense_[static_cast<std::size_t>(base + dense_offset_[k])];
      out[count] = f;  // branch-free: occupancy is a coin flip for the predictor
      count += f != kNone;
    }
  } else {
    for (std::int64_t dz = -1; dz <= 1; ++dz)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
          const std::uint32_t f = find({cc.x + dx, cc.y + dy, cc.z + dz});
          if (f != kNone) out[count++] = f;
        }
  }
  return count;
}

std::size_t CellGrid::memory_bytes() const {
  return pcoord_.capacity() * sizeof(CellCoord) + (keys_.capacity() + keys_tmp_.capacity()) * sizeof(KeyIndex) +
         dense_.capacity() * sizeof(std::uint32_t) + sorted_.capacity() * sizeof(std::uint32_t) +
         cell_of_.capacity() * sizeof(std::uint32_t) + coord_.capacity() * sizeof(CellCoord) +
         start_.capacity() * sizeof(std::uint32_t) + table_.capacity() * sizeof(std::uint32_t) + 0;
}

}  // namespace mpdem
