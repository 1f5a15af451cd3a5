#pragma once
// Sparse linked cells (physics.md section 11 and its Departure): particles are binned into cubic
// cells of a given side, sorted by the Morton (Z-order) key of their cell, and only occupied
// cells are stored. Occupied cells are found again through an open-addressing hash table, so
// memory is O(N) however far apart the particles are (one particle a kilometre away adds one
// cell, not a kilometre of grid). Nothing here allocates per particle or per contact.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec3.hpp"

namespace mpdem {

// Loops shorter than this run on one thread: an OpenMP region would cost more than it saves.
// (Results never depend on it: every parallel loop here is thread-count independent.)
inline constexpr std::size_t kNeighborParallelMin = 1024;

// Integer cell coordinates, relative to the grid origin (the componentwise minimum of the
// particle centres at build time), so every built particle has coordinates >= 0.
struct CellCoord {
  std::int64_t x = 0, y = 0, z = 0;
  friend constexpr bool operator==(const CellCoord&, const CellCoord&) = default;
};

// Strict Z-order comparison of two non-negative cell coordinates of any magnitude (compares
// the axis whose coordinates differ in the most significant bit; z wins ties, then y). Equal to
// comparing morton_key() whenever both fit in 21 bits per axis.
bool morton_less(const CellCoord& a, const CellCoord& b);
// 63-bit interleaved key (bit 3k = x bit k, 3k+1 = y bit k, 3k+2 = z bit k); requires
// 0 <= coordinates < 2^21.
std::uint64_t morton_key(const CellCoord& c);

class CellGrid {
 public:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;  // "no cell" from find()

  // Bins positions x [N] (m) into cells of side >= cell_side (m). The side is enlarged only
  // when it would need more than 2^30 cells along an axis, or when cell_side <= 0; a larger
  // side never loses a neighbour. Throws std::invalid_argument on a non-finite position.
  // find_neighbors = false skips the cell lookup index and the 27-cell neighbourhoods (enough
  // for sorted() alone; find() and neighbor_cells() are then unavailable).
  void build(std::span<const Vec3> x, double cell_side, bool find_neighbors = true);

  std::size_t num_particles() const { return sorted_.size(); }
  std::size_t num_cells() const { return coord_.size(); }
  double cell_side() const { return side_; }      // m
  const Vec3& origin() const { return origin_; }  // m, corner of cell (0, 0, 0)
  // Cells along axis a (0: x) spanned by the particles: occupied coordinates are in [0, dim(a)).
  std::int64_t dim(int a) const { return dims_[a]; }

  // Particle indices in cell (Morton) order; within a cell ascending by index [N].
  std::span<const std::uint32_t> sorted() const { return sorted_; }
  // First position in sorted() of each cell, plus the end [num_cells + 1].
  std::span<const std::uint32_t> cell_start() const { return start_; }
  std::span<const std::uint32_t> cell_particles(std::size_t c) const {
    return std::span<const std::uint32_t>(sorted_).subspan(start_[c], start_[c + 1] - start_[c]);
  }
  std::uint32_t cell_of(std::size_t i) const { return cell_of_[i]; }  // cell of particle i
  const CellCoord& coord(std::size_t c) const { return coord_[c]; }
  // Occupied cells among the 3x3x3 block around cell c (c included), in (dz, dy, dx) order,
  // written to out; returns how many. Found on demand (a stored 27-slot table per cell would
  // be the largest array of the grid).
  int neighbor_cells(std::size_t c, std::uint32_t out[27]) const;

  CellCoord coord_of(const Vec3& p) const;       // cell containing point p (may be unoccupied)
  std::uint32_t find(const CellCoord& c) const;  // cell index, or kNone if no particle is in it

  // Bytes held by all containers (capacity), for the O(N) memory check.
  std::size_t memory_bytes() const;
  std::size_t hash_slots() const { return table_.size(); }
  std::size_t dense_slots() const { return dense_.size(); }
  // True when the sort used 63-bit Morton keys (< 2^21 cells per axis), false when it used the
  // bitwise Z-order comparison; same order either way, exposed so tests can cover both.
  bool uses_morton_key() const { return morton_fast_; }
  // True when cells are found through a dense array over the bounding box (used only when that
  // box has at most kDenseFactor N cells, so memory stays O(N)); false: through the hash table.
  bool uses_dense_index() const { return !dense_.empty(); }
  static constexpr double kDenseFactor = 8.0;

 private:
  struct KeyIndex {  // radix-sort record: Morton key of the particle's cell, particle index
    std::uint64_t key;
    std::uint32_t index;
  };
  void sort_particles(std::size_t n);
  void index_cells(bool find_neighbors);
  std::size_t slot_of(const CellCoord& c) const;

  double side_ = 1.0;      // m
  double inv_side_ = 1.0;  // 1/m
  Vec3 origin_{};          // m
  bool morton_fast_ = true;
  std::int64_t dims_[3] = {0, 0, 0};       // cells per axis spanned by the particles
  std::vector<CellCoord> pcoord_;          // [N] cell coordinates of each particle (build only)
  std::vector<KeyIndex> keys_, keys_tmp_;  // [N] sort scratch (Morton-key path only, build only)
  std::vector<std::uint32_t> sorted_;      // [N] particle index in cell order
  std::vector<std::uint32_t> cell_of_;     // [N] cell index of each particle
  std::vector<CellCoord> coord_;           // [C] occupied cells, Morton order
  std::vector<std::uint32_t> start_;       // [C+1] offsets into sorted_
  std::vector<std::uint32_t> table_;       // [power of two >= 2C] hash slots -> cell (sparse sets)
  std::vector<std::uint32_t> dense_;       // [<= 8N] x-fastest box cells -> cell (compact sets)
  std::int64_t dense_offset_[27] = {};     // slot offsets of the 27 neighbours in dense_
};

}  // namespace mpdem
