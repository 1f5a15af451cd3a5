#include "neighbor/pair_blocks.hpp"

#include <stdexcept>

namespace mpdem {

void PairBlocks::build(const VerletList& list) {
  const std::size_t n = list.size();
  const auto& off = list.offsets();
  const auto& idx = list.indices();
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  if (2 * idx.size() >= (std::size_t{1} << 32))
    throw std::invalid_argument("pair blocks: too many pairs for 32-bit cross indices");

  // Cross pairs per block, and per particle how many it is a member of.
  cross_base_.assign(blocks + 1, 0);
  std::vector<std::uint32_t> count(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t end = block_end(i, n);
    for (std::size_t k = off[i]; k < off[i + 1]; ++k)
      if (idx[k] >= end) {
        ++cross_base_[i / kBlock + 1];
        ++count[i];
        ++count[idx[k]];
      }
  }
  for (std::size_t b = 0; b < blocks; ++b) cross_base_[b + 1] += cross_base_[b];

  particle_.clear();
  offset_.assign(1, 0);
  std::vector<std::uint32_t> slot_of(n, 0);  // member number of each particle
  for (std::size_t i = 0; i < n; ++i)
    if (count[i] > 0) {
      slot_of[i] = static_cast<std::uint32_t>(particle_.size());
      particle_.push_back(static_cast<std::uint32_t>(i));
      offset_.push_back(offset_.back() + count[i]);
    }
  entry_.resize(offset_.back());
  // Fill: own cross slots first (ascending), then the incoming ones (ascending cross index).
  // Pass 1 writes first-member entries, pass 2 second-member entries after them.
  std::vector<std::uint32_t> fill(particle_.size());
  for (std::size_t m = 0; m < particle_.size(); ++m) fill[m] = offset_[m];
  for (int pass = 0; pass < 2; ++pass) {
    std::uint32_t c = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t end = block_end(i, n);
      for (std::size_t k = off[i]; k < off[i + 1]; ++k) {
        if (idx[k] < end) continue;
        if (pass == 0)
          entry_[fill[slot_of[i]]++] = c << 1;
        else
          entry_[fill[slot_of[idx[k]]]++] = (c << 1) | 1u;
        ++c;
      }
    }
  }
}

std::size_t PairBlocks::memory_bytes() const {
  return cross_base_.capacity() * sizeof(std::size_t) +
         (particle_.capacity() + offset_.capacity() + entry_.capacity()) * sizeof(std::uint32_t);
}

}  // namespace mpdem
