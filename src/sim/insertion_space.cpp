#include "sim/insertion_space.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/triangle_closest_point.hpp"

namespace mpdem {

namespace {
// m^2, squared distance from x to the box [lo, hi] (0 inside).
double box_distance2(const Vec3& x, const Vec3& lo, const Vec3& hi) {
  double d2 = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double d = std::max({lo[a] - x[a], 0.0, x[a] - hi[a]});
    d2 += d * d;
  }
  return d2;
}

// Cells of side `side` on either side of a point that can hold a sphere reaching it (reach, m).
std::int64_t cells_within(double reach, double side) { return static_cast<std::int64_t>(std::ceil(reach / side)); }
}  // namespace

InsertionSpace::InsertionSpace(const Particles& p, const Barriers& b, const Vec3& lo, const Vec3& hi, double cell_hint)
    : lo_(lo) {
  for (std::size_t i = 0; i < p.size(); ++i)
    if (box_distance2(p.x[i], lo, hi) < p.radius[i] * p.radius[i]) {
      x_.push_back(p.x[i]);
      r_.push_back(p.radius[i]);
      r_max_ = std::max(r_max_, p.radius[i]);
    }
  side_ = 2.0 * std::max(r_max_, cell_hint);
  if (!x_.empty()) grid_.build(x_, side_);
  for (std::size_t e = 0; e < b.size(); ++e) {
    if (!b.active[e]) continue;  // switched off: in no contact
    const std::array<Vec3, 3> t{b.vertex(e, 0), b.vertex(e, 1), b.vertex(e, 2)};
    const double h = 0.5 * b.thickness[e];
    bool meets = true;  // the triangle's bounding box, thickened by h, meets the box
    for (int a = 0; a < 3; ++a) {
      const double tlo = std::min({t[0][a], t[1][a], t[2][a]}) - h, thi = std::max({t[0][a], t[1][a], t[2][a]}) + h;
      meets = meets && tlo <= hi[a] && thi >= lo[a];
    }
    if (!meets) continue;
    tri_.push_back(t);
    half_t_.push_back(h);
  }
}

InsertionSpace::Cell InsertionSpace::cell_of(const Vec3& x) const {
  return {static_cast<std::int64_t>(std::floor((x.x - lo_.x) / side_)),
          static_cast<std::int64_t>(std::floor((x.y - lo_.y) / side_)),
          static_cast<std::int64_t>(std::floor((x.z - lo_.z) / side_))};
}

bool InsertionSpace::free(const Vec3& x, double r) const {
  const auto clear = [&](const Vec3& c, double rc) {
    const double d = r + rc;
    return !(norm2(x - c) < d * d);
  };
  if (!x_.empty()) {
    const double side = grid_.cell_side();
    const std::int64_t k = cells_within(r + r_max_, side);
    const CellCoord c = grid_.coord_of(x);
    for (std::int64_t dz = -k; dz <= k; ++dz)
      for (std::int64_t dy = -k; dy <= k; ++dy)
        for (std::int64_t dx = -k; dx <= k; ++dx) {
          const std::uint32_t cell = grid_.find({c.x + dx, c.y + dy, c.z + dz});
          if (cell == CellGrid::kNone) continue;
          for (const std::uint32_t j : grid_.cell_particles(cell))
            if (!clear(x_[j], r_[j])) return false;
        }
  }
  if (!placed_x_.empty()) {
    const std::int64_t k = cells_within(r + r_max_, side_);
    const Cell c = cell_of(x);
    for (std::int64_t dz = -k; dz <= k; ++dz)
      for (std::int64_t dy = -k; dy <= k; ++dy)
        for (std::int64_t dx = -k; dx <= k; ++dx) {
          const auto it = placed_cells_.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == placed_cells_.end()) continue;
          for (const std::uint32_t j : it->second)
            if (!clear(placed_x_[j], placed_r_[j])) return false;
        }
  }
  for (std::size_t e = 0; e < tri_.size(); ++e) {
    const TriangleClosestPoint cp = closest_point_on_triangle(x, tri_[e][0], tri_[e][1], tri_[e][2]);
    const double d = r + half_t_[e];
    if (norm2(x - cp.point) < d * d) return false;
  }
  return true;
}

void InsertionSpace::add(const Vec3& x, double r) {
  placed_cells_[cell_of(x)].push_back(static_cast<std::uint32_t>(placed_x_.size()));
  placed_x_.push_back(x);
  placed_r_.push_back(r);
  r_max_ = std::max(r_max_, r);
}

}  // namespace mpdem
