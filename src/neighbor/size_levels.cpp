#include "neighbor/size_levels.hpp"

#include <algorithm>
#include <cmath>

#include "neighbor/cell_grid.hpp"

namespace mpdem {

SizeLevels size_levels(std::span<const double> radius) {
  const std::size_t n = radius.size();
  double lo = HUGE_VAL, hi = 0.0;
#pragma omp parallel for schedule(static) reduction(min : lo) reduction(max : hi) if (n >= kNeighborParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    lo = std::min(lo, radius[i]);
    hi = std::max(hi, radius[i]);
  }
  SizeLevels s;
  if (n == 0) return s;
  s.r_min = lo;
  if (!(lo > 0.0) || hi < 2.0 * lo) {  // one level: the single grid of the narrow distributions
    s.r_max = {hi};
    return s;
  }
  s.level.resize(n);
  const double inv = 1.0 / lo;
  // ilogb is exact (the binary exponent), so a level never depends on rounding of a logarithm.
  int top = 0;
#pragma omp parallel for schedule(static) reduction(max : top) if (n >= kNeighborParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    const int l = std::clamp(std::ilogb(radius[i] * inv), 0, SizeLevels::kMaxLevels - 1);
    s.level[i] = static_cast<std::uint8_t>(l);
    top = std::max(top, l);
  }
  s.r_max.assign(static_cast<std::size_t>(top) + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    double& m = s.r_max[s.level[i]];
    m = std::max(m, radius[i]);
  }
  return s;
}

}  // namespace mpdem
