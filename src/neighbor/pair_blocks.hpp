#pragma once
// PairBlocks: fixed blocks of consecutive particles over a half Verlet list, for pair loops that
// add each pair's force straight into both particles without races and with sums that do not
// depend on the number of threads.
//
// Block b holds particles [b B, (b+1) B), B = block_size(n). A pair (i, j), i < j, is *internal* when j is
// in i's block, else a *cross* pair. One thread processes a whole block in slot order and adds
// each pair's result straight to its first member i (always in the block) and, for an internal
// pair, to j; so every particle's sum has the same order for any thread count. A cross pair's
// share for j goes to a buffer at its cross index (numbered in slot order, block by block; they
// are the tail of i's ascending slot range), and a second pass adds the buffer to each second
// member in ascending cross index. With the particles in space-filling-curve order (reordered
// at rebuilds) most pairs are internal.
//
// Why B depends on n: the threads take whole blocks, so a system of few blocks cannot be split
// evenly (20k particles in blocks of 4096: five blocks, 3 against 2 on two threads). B is the
// largest power of two in [kMinBlock, kMaxBlock] that still gives kTargetBlocks blocks: a
// function of the particle count alone, never of the thread count, so the sums keep their order
// for any number of threads. Larger blocks keep more pairs internal (cheaper than cross pairs).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "neighbor/verlet_list.hpp"

namespace mpdem {

class PairBlocks {
 public:
  static constexpr std::size_t kMinBlock = 512;    // particles per block, at least
  static constexpr std::size_t kMaxBlock = 4096;   // and at most
  static constexpr std::size_t kTargetBlocks = 8;  // blocks wanted, for an even split over threads

  // Particles per block for n particles (a power of two).
  static std::size_t block_size(std::size_t n);

  void build(const VerletList& list);
  void clear() { *this = PairBlocks{}; }  // frees everything: no blocks until the next build

  std::size_t num_blocks() const { return cross_base_.size() - 1; }
  std::size_t num_cross() const { return cross_base_.back(); }
  std::size_t block() const { return block_; }  // particles per block, of the last build
  // First particle of block b, and the end (exclusive) of the block that holds particle i:
  // pair (i, j) is internal iff j < block_end(i).
  std::size_t block_begin(std::size_t b) const { return b * block_; }
  std::size_t block_end(std::size_t i) const {
    const std::size_t e = (i / block_ + 1) * block_;
    return e < n_ ? e : n_;
  }
  // First cross index of block b.
  std::size_t cross_base(std::size_t b) const { return cross_base_[b]; }
  // First member of every slot of the list: a block's slots are then one flat loop, without
  // the hard-to-predict exit of a per-particle loop of 0-8 neighbours.
  const std::vector<std::uint32_t>& first_members() const { return first_; }

  // Particles that are the second member of cross pairs, ascending; entries(m) are the cross
  // indices of the m-th of them, ascending.
  const std::vector<std::uint32_t>& cross_particles() const { return particle_; }
  std::span<const std::uint32_t> entries(std::size_t m) const {
    return {entry_.data() + offset_[m], offset_[m + 1] - offset_[m]};
  }
  std::size_t memory_bytes() const;

 private:
  std::size_t block_ = kMaxBlock;           // particles per block
  std::size_t n_ = 0;                       // particles (with ghosts) of the last build
  std::vector<std::size_t> cross_base_{0};  // [blocks + 1] cross indices before each block
  std::vector<std::uint32_t> particle_;     // [members] second members of cross pairs
  std::vector<std::uint32_t> offset_{0};    // [members + 1] CSR offsets into entry_
  std::vector<std::uint32_t> entry_;        // [cross] cross indices
  std::vector<std::uint32_t> first_;        // [pairs] first member of each slot
};

}  // namespace mpdem
