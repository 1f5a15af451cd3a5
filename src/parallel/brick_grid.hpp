#pragma once
// BrickGrid: the Cartesian (brick) decomposition of the domain over the ranks of a run
// (docs/parallel.md). dims[c] bricks along axis c, separated by interior cut planes; the outer
// bricks of a non-periodic axis reach to infinity, so every point has exactly one owner. Along a
// periodic axis the bricks tile the period and the first and last are neighbours. Ranks are
// numbered x fastest: rank = cx + dims_x (cy + dims_y cz).
#include <array>
#include <span>
#include <vector>

#include "core/vec3.hpp"

namespace mpdem {

class BrickGrid {
 public:
  BrickGrid() = default;
  // `ranks` bricks over the box [lo, hi] (m), cut uniformly; dims chosen by choose_dims.
  BrickGrid(int ranks, const Vec3& lo, const Vec3& hi, const std::array<bool, 3>& periodic);

  // The factorisation dims_x dims_y dims_z = ranks of least cut area for a box of this extent (m):
  // the sum over axes of (dims_c - 1) x the box's cross-section normal to c, plus, along a
  // periodic axis, the face between the last and the first brick. Ties go to cutting x first.
  static std::array<int, 3> choose_dims(int ranks, const Vec3& extent, const std::array<bool, 3>& periodic);

  int ranks() const { return dims_[0] * dims_[1] * dims_[2]; }
  const std::array<int, 3>& dims() const { return dims_; }
  std::array<int, 3> coords(int rank) const;
  int rank_at(const std::array<int, 3>& c) const;
  // Brick index along axis c holding coordinate x (m): below the first interior cut 0, at or
  // above the last dims - 1 (the outer bricks are unbounded; a periodic coordinate is wrapped first).
  int brick_along(int c, double x) const;
  int owner(const Vec3& x) const;
  // mask[i] = 1 when `rank` owns the point x[i] (the particles a rank keeps).
  std::vector<char> owned(std::span<const Vec3> x, int rank) const;
  // The rank next to `rank` along axis c in direction dir (-1 or +1): across the periodic face
  // for the first and last brick of a periodic axis; -1 when there is none.
  int neighbour(int rank, int c, int dir) const;
  // m, the brick's faces along c: the box's min and max at the ends of a periodic axis,
  // -inf / +inf at the ends of a non-periodic one.
  double lower(int rank, int c) const;
  double upper(int rank, int c) const;
  // Interior cut planes along c (dims_c - 1 values, ascending, m); set_cuts moves them (load balance).
  const std::vector<double>& cuts(int c) const { return cuts_[static_cast<std::size_t>(c)]; }
  void set_cuts(int c, std::vector<double> planes);
  // m, the narrowest brick along a decomposed axis (infinity when no axis is cut): a halo of width
  // w reaches only the neighbours when every brick is at least w wide.
  double narrowest() const;
  const Vec3& box_lower() const { return lo_; }
  const Vec3& box_upper() const { return hi_; }
  const std::array<bool, 3>& periodic() const { return periodic_; }

 private:
  std::array<int, 3> dims_{1, 1, 1};
  std::array<std::vector<double>, 3> cuts_;
  std::array<bool, 3> periodic_{};
  Vec3 lo_{}, hi_{};
};

}  // namespace mpdem
