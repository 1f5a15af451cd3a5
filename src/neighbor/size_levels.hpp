#pragma once
// Size levels for wide radius distributions (docs/neighbor_search.md, "Size levels"): particle i
// belongs to level floor(log2(R_i / R_min)), so within a level the radii differ by less than a
// factor 2. The Verlet list bins each level in cells sized for that level's largest pair range,
// so a few large spheres no longer make the cells of the small ones large (the multilevel grid of
// Ogarko and Luding, Comput. Phys. Commun. 183 (2012) 931; LAMMPS's `neighbor multi`).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace mpdem {

struct SizeLevels {
  static constexpr int kMaxLevels = 16;  // radius ratios beyond 2^16 share the last level
  double r_min = 0.0;                    // m, smallest radius
  std::vector<double> r_max;             // [levels] m, largest radius of each level (0: empty level)
  std::vector<std::uint8_t> level;       // [N] level of each particle (empty when one level)

  std::size_t count() const { return r_max.size(); }
  // Radius of the smallest level's largest particle (m): the cell side of the finest grid.
  double finest_r_max() const { return r_max.empty() ? 0.0 : r_max.front(); }
};

// Levels of the radii radius [N] (m, finite, >= 0). One level (and no per-particle array) when
// every radius is below 2 R_min, or when some radius is 0.
SizeLevels size_levels(std::span<const double> radius);

}  // namespace mpdem
