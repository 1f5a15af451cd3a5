#pragma once
// Below this many items a parallel region costs more than it saves (and oversubscribed cores
// make idle OpenMP threads expensive), so loops run serially: `#pragma omp parallel for
// if (n > kParallelThreshold)`. Results never depend on it: every parallel loop writes
// per-item results or reduces deterministically.
#include <cstddef>

namespace mpdem {
inline constexpr std::size_t kParallelThreshold = 2048;
}  // namespace mpdem
