#pragma once
// PairBlocks: fixed blocks of consecutive particles over a half Verlet list, for pair loops that
// add each pair's force straight into both particles without races and with sums that do not
// depend on the number of threads.
//
// Block b holds particles [b kBlock, (b+1) kBlock). A pair (i, j), i < j, is *internal* when j is
// in i's block: one thread processes the whole block in index order, so it may add to both
// members, and every particle's sum has the same order for any thread count. The other pairs
// are *cross* pairs: since the neighbours of i are ascending, they are the tail of i's slot
// range. A cross pair's result goes to a buffer at its cross index (numbered in slot order,
// block by block), and a second pass adds the buffer to both members in a fixed order (the
// particle's own cross slots, then those where it is the second member, each ascending).
// With the particles in space-filling-curve order (reordered at rebuilds) most pairs are
// internal.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "neighbor/verlet_list.hpp"

namespace mpdem {

class PairBlocks {
 public:
  static constexpr std::size_t kBlock = 1024;  // particles per block (a fixed constant: results
                                               // must not depend on it changing with threads)

  void build(const VerletList& list);

  std::size_t num_blocks() const { return cross_base_.size() - 1; }
  std::size_t num_cross() const { return cross_base_.back(); }
  // End (exclusive) of the block that holds particle i: pair (i, j) is internal iff j < block_end(i).
  static std::size_t block_end(std::size_t i, std::size_t n) {
    const std::size_t e = (i / kBlock + 1) * kBlock;
    return e < n ? e : n;
  }
  // First cross index of block b.
  std::size_t cross_base(std::size_t b) const { return cross_base_[b]; }

  // Particles that are members of cross pairs, ascending; entries(m) are the cross indices of
  // the m-th of them, each shifted left by one, with bit 0 set when it is the second member.
  const std::vector<std::uint32_t>& cross_particles() const { return particle_; }
  std::span<const std::uint32_t> entries(std::size_t m) const {
    return {entry_.data() + offset_[m], offset_[m + 1] - offset_[m]};
  }
  std::size_t memory_bytes() const;

 private:
  std::vector<std::size_t> cross_base_{0};  // [blocks + 1] cross indices before each block
  std::vector<std::uint32_t> particle_;     // [members] particles with cross pairs
  std::vector<std::uint32_t> offset_{0};    // [members + 1] CSR offsets into entry_
  std::vector<std::uint32_t> entry_;        // [2 cross] (cross index << 1) | second-member bit
};

}  // namespace mpdem
