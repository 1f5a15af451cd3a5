#pragma once
// The gap rule of bonds (docs/scene.md "[bonds]"): particles i and j are bonded when their surface
// gap |x_j - x_i| - r_i - r_j is below `gap`.
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "core/vec3.hpp"

namespace mpdem {

// The pairs (i, j), i < j, of indices into x and r whose surface gap is below `gap` (m, >= 0),
// sorted. x: m, centres, shape [n]; r: m, radii, shape [n]. O(n) with a cell grid.
std::vector<std::array<std::size_t, 2>> gap_pairs(const std::vector<Vec3>& x, const std::vector<double>& r, double gap);

// The surface gap of the rule (m), the same arithmetic as gap_pairs.
inline double surface_gap(const Vec3& xi, double ri, const Vec3& xj, double rj) {
  return std::sqrt(norm2(xj - xi)) - ri - rj;
}

}  // namespace mpdem
