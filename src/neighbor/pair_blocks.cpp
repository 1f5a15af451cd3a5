#include "neighbor/pair_blocks.hpp"

#include <bit>
#include <stdexcept>

namespace mpdem {

std::size_t PairBlocks::block_size(std::size_t n) {
  const std::size_t b = std::bit_floor(n / kTargetBlocks);  // 0 for n < kTargetBlocks
  return b < kMinBlock ? kMinBlock : b > kMaxBlock ? kMaxBlock : b;
}

void PairBlocks::build(const VerletList& list) {
  const std::size_t n = list.size();
  const auto& off = list.offsets();
  const auto& idx = list.indices();
  block_ = block_size(n);
  n_ = n;
  const std::size_t blocks = (n + block_ - 1) / block_;
  if (idx.size() >= (std::size_t{1} << 32))
    throw std::invalid_argument("pair blocks: too many pairs for 32-bit slot and cross indices");

  // Cross pairs per block, and per particle how many it is the second member of.
  cross_base_.assign(blocks + 1, 0);
  first_.resize(idx.size());
  std::vector<std::uint32_t> count(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t end = block_end(i);
    for (std::size_t k = off[i]; k < off[i + 1]; ++k) first_[k] = static_cast<std::uint32_t>(i);
    for (std::size_t k = off[i]; k < off[i + 1]; ++k)
      if (idx[k] >= end) {
        ++cross_base_[i / block_ + 1];
        ++count[idx[k]];
      }
  }
  for (std::size_t b = 0; b < blocks; ++b) cross_base_[b + 1] += cross_base_[b];

  particle_.clear();
  offset_.assign(1, 0);
  std::vector<std::uint32_t> fill(n, 0);  // next entry of each second member
  for (std::size_t i = 0; i < n; ++i)
    if (count[i] > 0) {
      fill[i] = offset_.back();
      particle_.push_back(static_cast<std::uint32_t>(i));
      offset_.push_back(offset_.back() + count[i]);
    }
  entry_.resize(offset_.back());
  std::uint32_t c = 0;  // cross index, ascending: each member's entries come out ascending
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t end = block_end(i);
    for (std::size_t k = off[i]; k < off[i + 1]; ++k)
      if (idx[k] >= end) entry_[fill[idx[k]]++] = c++;
  }
}

std::size_t PairBlocks::memory_bytes() const {
  return cross_base_.capacity() * sizeof(std::size_t) +
         (particle_.capacity() + offset_.capacity() + entry_.capacity() + first_.capacity()) * sizeof(std::uint32_t);
}

}  // namespace mpdem
