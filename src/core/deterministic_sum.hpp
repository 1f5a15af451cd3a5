#pragma once
// Sums f(i) over i in [0, n) in parallel with a result that does not depend on the number of
// threads: fixed-size blocks are summed independently, then the block sums in order.
#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "core/parallel.hpp"

namespace mpdem {

// g(lo, hi, acc) adds the terms of indices [lo, hi), one fixed block, to acc in index order.
template <int K, class G>
std::array<double, K> deterministic_block_sums(std::size_t n, G&& g) {
  constexpr std::size_t kBlock = 1024;
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  std::vector<std::array<double, K>> partial(blocks);
#pragma omp parallel for schedule(static) if (n > kParallelThreshold)
  for (std::size_t blk = 0; blk < blocks; ++blk) {
    std::array<double, K> s{};
    g(blk * kBlock, std::min(n, (blk + 1) * kBlock), s);
    partial[blk] = s;
  }
  std::array<double, K> total{};
  for (const auto& s : partial)
    for (int k = 0; k < K; ++k) total[k] += s[k];
  return total;
}

template <int K, class F>
std::array<double, K> deterministic_sums(std::size_t n, F&& f) {
  return deterministic_block_sums<K>(n, [&](std::size_t lo, std::size_t hi, std::array<double, K>& s) {
    for (std::size_t i = lo; i < hi; ++i) f(i, s);
  });
}

}  // namespace mpdem
