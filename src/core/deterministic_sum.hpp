#pragma once
// Sums f(i) over i in [0, n) in parallel with a result that does not depend on the number of
// threads: fixed-size blocks are summed independently, then the block sums in order.
#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "core/parallel.hpp"

namespace mpdem {

inline constexpr std::size_t kSumBlock = 1024;  // items per block of the sums below

// The number of blocks of n items.
inline std::size_t sum_blocks(std::size_t n) { return (n + kSumBlock - 1) / kSumBlock; }

// The blocks' sums as an orphaned work-sharing loop: every thread of a team calls it (or one
// thread outside a parallel region). partial [sum_blocks(n)] (shared) receives each block's sums;
// block_total adds them after a barrier (the loop has none: the region's end is one).
template <int K, class G>
void block_sums_in_team(std::size_t n, std::vector<std::array<double, K>>& partial, G&& g) {
#pragma omp for schedule(static) nowait
  for (std::size_t blk = 0; blk < partial.size(); ++blk) {
    std::array<double, K> s{};
    g(blk * kSumBlock, std::min(n, (blk + 1) * kSumBlock), s);
    partial[blk] = s;
  }
}

// The blocks' sums in block order.
template <int K>
std::array<double, K> block_total(const std::vector<std::array<double, K>>& partial) {
  std::array<double, K> total{};
  for (const auto& s : partial)
    for (int k = 0; k < K; ++k) total[k] += s[k];
  return total;
}

// g(lo, hi, acc) adds the terms of indices [lo, hi), one fixed block, to acc in index order.
template <int K, class G>
std::array<double, K> deterministic_block_sums(std::size_t n, G&& g) {
  std::vector<std::array<double, K>> partial(sum_blocks(n));
#pragma omp parallel if (n > kParallelThreshold)
  block_sums_in_team<K>(n, partial, g);
  return block_total<K>(partial);
}

template <int K, class F>
std::array<double, K> deterministic_sums(std::size_t n, F&& f) {
  return deterministic_block_sums<K>(n, [&](std::size_t lo, std::size_t hi, std::array<double, K>& s) {
    for (std::size_t i = lo; i < hi; ++i) f(i, s);
  });
}

}  // namespace mpdem
