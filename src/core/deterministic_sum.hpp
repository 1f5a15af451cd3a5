#pragma once
// Sums f(i) over i in [0, n) in parallel with a result that does not depend on the number of
// threads: fixed-size blocks are summed independently, then the block sums in order.
#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "core/parallel.hpp"

namespace mpdem {

template <int K, class F>
std::array<double, K> deterministic_sums(std::size_t n, F&& f) {
  constexpr std::size_t kBlock = 1024;
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  std::vector<std::array<double, K>> partial(blocks);
#pragma omp parallel for schedule(static) if (n > kParallelThreshold)
  for (std::size_t blk = 0; blk < blocks; ++blk) {
    std::array<double, K> s{};
    const std::size_t end = std::min(n, (blk + 1) * kBlock);
    for (std::size_t i = blk * kBlock; i < end; ++i) f(i, s);
    partial[blk] = s;
  }
  std::array<double, K> total{};
  for (const auto& s : partial)
    for (int k = 0; k < K; ++k) total[k] += s[k];
  return total;
}

}  // namespace mpdem
