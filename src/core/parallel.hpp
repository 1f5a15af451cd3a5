#pragma once
// Below this many items a parallel region costs more than it saves (and oversubscribed cores
// make idle OpenMP threads expensive), so loops run serially: `#pragma omp parallel for
// if (n > kParallelThreshold)`. Results never depend on it: every parallel loop writes
// per-item results or reduces deterministically.
#include <cstddef>

namespace mpdem {
inline constexpr std::size_t kParallelThreshold = 2048;

// Splits items [0, count) into `threads` runs of consecutive items of about equal weight and
// returns where run r starts (run `threads` starts at count). weight_before(b) is the total
// weight of the items before b, non-decreasing in b. For loops whose items differ in cost (blocks
// of particles with different numbers of contacts): equal numbers of items can leave a thread
// idle much of the time. Callers keep per-item results, so the split never changes them.
template <class W>
std::size_t balanced_split(int r, int threads, std::size_t count, W&& weight_before) {
  if (r <= 0) return 0;
  if (r >= threads) return count;
  const double target = static_cast<double>(weight_before(count)) * r / threads;
  std::size_t lo = 0, hi = count;  // the first item whose weight before it reaches target
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (static_cast<double>(weight_before(mid)) < target) lo = mid + 1;
    else hi = mid;
  }
  // The nearer of the two boundaries around the target (items can be coarse).
  if (lo > 0 && target - static_cast<double>(weight_before(lo - 1)) < static_cast<double>(weight_before(lo)) - target)
    --lo;
  return lo;
}
}  // namespace mpdem
