#pragma once
// Spatial reordering for cache locality: particles close in space get close indices, so the
// pair loop touches nearby memory. The order follows the Z-order (Morton) curve over the cells
// of the sparse grid, and within a cell the current index order (so it is deterministic).
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec3.hpp"

namespace mpdem {

// x [N] m centres; cell_side (m): typically the neighbour-search cell side (2 R_max + extra +
// skin). Returns order [N], a permutation of 0..N-1 for Particles::permute (new index k holds
// old particle order[k]). Neighbour lists and contact-history indices must be rebuilt/remapped
// after applying it.
std::vector<std::uint32_t> spatial_order(std::span<const Vec3> x, double cell_side);

}  // namespace mpdem
