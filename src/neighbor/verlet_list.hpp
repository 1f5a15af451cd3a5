#pragma once
// Verlet neighbour list with skin (physics.md section 11), built from the sparse cell grid.
//
// Half list in CSR form: the pair {i, j} is stored once, under the smaller index i (i < j in the
// index order at build time), so a pair loop can apply f_ji = -f_ij. The neighbours of i are
// indices()[offsets()[i] .. offsets()[i+1]), ascending. The pair is listed when
//     |x_i - x_j| < R_i + R_j + extra_range + skin
// (extra_range: e.g. a near-field cutoff beyond contact). The output depends only on the input,
// never on the number of threads.
//
// Verlet guarantee: while every particle has moved at most skin/2 since the build, every pair
// with |x_i - x_j| < R_i + R_j + extra_range is in the list. needs_rebuild() reports when that
// no longer holds. The list is tied to the index order: rebuild after permuting or adding
// particles, rebuild or compact() after removing some (a changed count is detected and reported
// as needing a rebuild).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "core/vec3.hpp"
#include "neighbor/cell_grid.hpp"
#include "neighbor/size_levels.hpp"

namespace mpdem {

class VerletList {
 public:
  // x [N] m centres, radius [N] m, skin >= 0 m, extra_range >= 0 m.
  // Throws std::invalid_argument for mismatched sizes, a negative/non-finite skin, extra range
  // or radius, a non-finite position, or more than 2^32 - 1 particles or pairs.
  void build(std::span<const Vec3> x, std::span<const double> radius, double skin, double extra_range = 0.0) {
    build(x, radius, skin, extra_range, x.size(), {});
  }
  // With ghosts (state/particles.hpp): particles [owned, N) are ghosts, listed only as second
  // members of owned ones, and pair (i, g) only when id[i] < id[g] (a ghost carries its source's
  // id): of the two images of a pair across a periodic boundary, (i, ghost of j) and (j, ghost
  // of i), exactly one is listed. id [N]. after_pairs, when given, runs once the pairs are
  // listed and before the build positions are stored (NeighborSearch::rebuild: peak memory).
  void build(std::span<const Vec3> x, std::span<const double> radius, double skin, double extra_range,
             std::size_t owned, std::span<const std::int64_t> id, const std::function<void()>& after_pairs = {});

  // Removes the particles whose keep[i] is 0 (a list without ghosts): the others keep their build
  // positions and pairs, in order, so the list is what a build at those positions would give
  // (a pair list only loses pairs when particles go) and stays valid as long as the rebuild rule
  // says. Returns the old slot of every kept slot, ascending.
  std::vector<std::uint32_t> compact(const std::vector<char>& keep);
  // Drops the pairs of two particles of one group (group[i] == group[j] != kNoGroup; group [N],
  // ghosts included): the member spheres of one rigid body never touch each other. Kept pairs stay
  // in order. Call between the build's listing and its after_pairs hook.
  static constexpr std::int64_t kNoGroup = -1;
  void drop_pairs_within_groups(std::span<const std::int64_t> group);
  // Frees the build positions before a rebuild (peak memory): the pairs stay readable, the list
  // counts as not built (needs_rebuild) until the next build.
  void release_build_positions();

  std::size_t size() const { return x_build_.size(); }  // N at the last build, ghosts included
  std::size_t owned() const { return owned_; }          // particles that are not ghosts
  std::size_t num_pairs() const { return index_.size(); }
  // Neighbours j > i of particle i, ascending.
  std::span<const std::uint32_t> neighbors(std::size_t i) const {
    return {index_.data() + offset_[i], offset_[i + 1] - offset_[i]};
  }
  const std::vector<std::uint32_t>& offsets() const { return offset_; }  // [N+1]
  const std::vector<std::uint32_t>& indices() const { return index_; }   // [num_pairs]

  // Largest |x_i - x_i(build)| (m) over the owned particles (ghosts follow them); x holds the
  // owned particles, with or without the ghosts. +infinity if the count changed since the build.
  double max_displacement(std::span<const Vec3> x) const;
  // True when some particle has moved strictly more than skin/2 since the build (or the count
  // changed, or the list was never built).
  bool needs_rebuild(std::span<const Vec3> x) const;
  // The same rule for a largest squared displacement max2 (m^2) measured elsewhere.
  bool needs_rebuild(double max2) const { return !built_ || max2 > half_skin2(); }
  bool built() const { return built_; }  // false before the first build and after release_build_positions

  double skin() const { return skin_; }                                  // m
  double half_skin2() const { return (0.5 * skin_) * (0.5 * skin_); }    // m^2, the rebuild threshold squared
  const std::vector<Vec3>& build_positions() const { return x_build_; }  // [N] m, at the last build (owned first)
  double extra_range() const { return extra_; }                          // m
  double max_radius() const { return max_radius_; }                      // m, at build
  // The cell grid of the last build. It and the build's scratch are freed when the build ends
  // (rebuilds are rare; between them the memory matters more), so only its figures are kept.
  struct GridStats {
    std::size_t cells = 0, hash_slots = 0, dense_slots = 0;
    std::size_t bytes = 0;                         // held by the grid during the build
    bool morton_key = false, dense_index = false;  // of every level's grid (false: some level's was not)
    std::size_t levels = 1;                        // size levels, one grid each (size_levels.hpp)
  };
  const GridStats& grid_stats() const { return grid_stats_; }
  std::size_t memory_bytes() const;  // bytes held between builds

 private:
  double skin_ = 0.0;        // m
  double extra_ = 0.0;       // m
  double max_radius_ = 0.0;  // m
  bool built_ = false;
  std::size_t owned_ = 0;
  GridStats grid_stats_;
  std::vector<Vec3> x_build_;             // [N] m, centres at build time
  std::vector<std::uint32_t> offset_{0};  // [N+1] CSR offsets (at most 2^32 - 1 pairs)
  std::vector<std::uint32_t> index_;      // [pairs] neighbour indices

  // The two searches behind build(), the same pairs either way: one grid for radii within a
  // factor 2, else a grid per size level (size_levels.hpp).
  void build_single(std::span<const Vec3> x, std::span<const double> radius, std::size_t owned,
                    std::span<const std::int64_t> id);
  void build_levels(std::span<const Vec3> x, std::span<const double> radius, const SizeLevels& levels,
                    std::size_t owned, std::span<const std::int64_t> id);
};

}  // namespace mpdem
