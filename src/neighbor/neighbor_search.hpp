#pragma once
// NeighborSearch: the Verlet pair list and the barrier candidate lists of a run, rebuilt only
// when needed (physics.md section 11): when the largest particle displacement plus the largest
// barrier displacement since the last build exceeds skin/2. Also the transposed pair index used
// to gather pair forces deterministically.
#include <cstdint>
#include <span>
#include <vector>

#include "io/binary_stream.hpp"
#include "neighbor/barrier_broadphase.hpp"
#include "neighbor/pair_blocks.hpp"
#include "neighbor/verlet_list.hpp"
#include "state/barriers.hpp"
#include "state/particles.hpp"

namespace mpdem {

class NeighborSearch {
 public:
  // skin [m] > 0; extra_range [m] >= 0 adds to the contact range (near-field cutoff).
  NeighborSearch(double skin, double extra_range) : skin_(skin), extra_(extra_range) {}

  bool needs_rebuild(const Particles& p, const Barriers& b) const;
  void rebuild(const Particles& p, const Barriers& b);
  // Checkpoints: the build positions of both lists, so a resumed run rebuilds at the same steps.
  void save(BinaryWriter& w) const;
  void restore(BinaryReader& r, const Particles& p, const Barriers& b);
  // Permutation sorting the particles along a space-filling curve (for cache locality).
  std::vector<std::uint32_t> spatial_order(const Particles& p) const;

  // The transposed pair index (incoming) costs 4 bytes per pair; it is built only for
  // the laws that gather per-slot values (heat conduction, near field). Takes effect at the
  // next rebuild.
  void set_incoming_index(bool on) { want_incoming_ = on; }

  const VerletList& pairs() const { return list_; }
  const PairBlocks& blocks() const { return blocks_; }
  const BarrierBroadphase& barrier_candidates() const { return broad_; }
  // Pair slots k (into pairs().indices()) whose second member is particle j, ascending
  // (set_incoming_index(true) only).
  std::span<const std::uint32_t> incoming(std::size_t j) const {
    return {in_slot_.data() + in_offset_[j], in_offset_[j + 1] - in_offset_[j]};
  }
  std::uint64_t rebuilds() const { return rebuilds_; }
  // Changes with every build (also a checkpoint restore): the particle order may have changed,
  // so caches indexed by particle must be refreshed.
  std::uint64_t generation() const { return generation_; }
  double skin() const { return skin_; }

 private:
  double skin_;
  double extra_;
  std::uint64_t rebuilds_ = 0;
  std::uint64_t generation_ = 0;
  std::vector<Vec3> barrier_offsets_build_;  // [M] m, barrier offsets at the last build
  bool rotating_build_ = false;              // the barriers rotate (their build time is checkpointed)
  double barrier_time_build_ = 0.0;          // s, Barriers::time at the last build
  VerletList list_;
  BarrierBroadphase broad_;
  PairBlocks blocks_;
  bool want_incoming_ = false;
  std::vector<std::size_t> in_offset_;  // [N+1] CSR offsets of the transposed index
  std::vector<std::uint32_t> in_slot_;  // [pairs] slots, grouped by second member

  void build(std::span<const Vec3> x, std::span<const double> radius, const Barriers& b);
};

}  // namespace mpdem
