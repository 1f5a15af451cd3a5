#pragma once
// InsertionSpace: whether a new sphere fits at a point of a box, clear of the particles and the
// active barrier elements there and of the spheres placed since (sim/inlets.hpp). Built once per
// insertion time from the state between two steps: only what reaches into the box is kept - the
// particles whose sphere meets it, binned in a CellGrid, and the elements whose triangle, thickened
// by t_b/2, meets it - so a check costs the few neighbours of the point, not N.
#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "core/vec3.hpp"
#include "neighbor/cell_grid.hpp"
#include "state/barriers.hpp"
#include "state/particles.hpp"

namespace mpdem {

class InsertionSpace {
 public:
  // lo, hi (m): the box every sphere to check lies in; cell_hint (m): a typical new radius.
  InsertionSpace(const Particles& p, const Barriers& b, const Vec3& lo, const Vec3& hi, double cell_hint);

  // True when the sphere (x, r) (m) overlaps nothing: its distance to every particle centre is at
  // least the sum of the radii, to every element at least r + t_b/2 (the contact distance).
  bool free(const Vec3& x, double r) const;
  // A sphere placed at x with radius r (m): later checks keep clear of it.
  void add(const Vec3& x, double r);

 private:
  using Cell = std::array<std::int64_t, 3>;
  Cell cell_of(const Vec3& x) const;  // cell of x in the placed spheres' grid

  std::vector<Vec3> x_;                   // m, centres of the particles meeting the box [K]
  std::vector<double> r_;                 // m, their radii [K]
  CellGrid grid_;                         // over x_ (built only when K > 0)
  double r_max_ = 0.0;                    // m, largest radius of x_ and of the placed spheres
  std::vector<std::array<Vec3, 3>> tri_;  // m, current vertices of the elements meeting the box [E]
  std::vector<double> half_t_;            // m, their t_b / 2 [E]
  // The spheres placed since construction: centres (m), radii (m), and their indices by cell
  // of side side_ from lo_.
  std::vector<Vec3> placed_x_;
  std::vector<double> placed_r_;
  std::map<Cell, std::vector<std::uint32_t>> placed_cells_;
  Vec3 lo_;            // m
  double side_ = 1.0;  // m, cell side of both grids
};

}  // namespace mpdem
