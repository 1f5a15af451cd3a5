#include "neighbor/spatial_order.hpp"

#include "neighbor/cell_grid.hpp"

namespace mpdem {

std::vector<std::uint32_t> spatial_order(std::span<const Vec3> x, double cell_side) {
  // The grid already sorts particles along the Morton curve of their cells; reuse that order.
  CellGrid grid;
  grid.build(x, cell_side, /*find_neighbors=*/false);
  const auto s = grid.sorted();
  return {s.begin(), s.end()};
}

}  // namespace mpdem
