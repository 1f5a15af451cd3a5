// Bonded pairs by the gap rule (docs/tools.md "mpdem agglomerate").
#include "generate/bond_pairs.hpp"

#include <algorithm>

#include "generate/sphere_cells.hpp"

namespace mpdem {

std::vector<std::array<std::size_t, 2>> gap_pairs(const std::vector<Vec3>& x, const std::vector<double>& r,
                                                  double gap) {
  std::vector<std::array<std::size_t, 2>> pairs;
  if (x.empty()) return pairs;
  Vec3 lo = x.front(), hi = x.front();  // m
  double r_max = 0.0;                   // m
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], x[i][a]);
      hi[a] = std::max(hi[a], x[i][a]);
    }
    r_max = std::max(r_max, r[i]);
  }
  // Cells a little wider than the longest bonded distance: rounding cannot hide a pair.
  SphereCells cells(lo, hi, (2.0 * r_max + gap) * (1.0 + 1e-9));
  cells.build(x);
  cells.each_pair([&](std::size_t i, std::size_t j) {
    if (surface_gap(x[i], r[i], x[j], r[j]) < gap) pairs.push_back({i, j});
  });
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace mpdem
