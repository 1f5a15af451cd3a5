#pragma once
// MeshSolid: the volume enclosed by a closed triangle surface, for mesh-bounded generator regions.
// Point membership by ray parity along +x (a column grid in y-z keeps it to the few triangles
// over the point, and an exact tie rule counts a ray through a shared edge or vertex once), and
// sphere clearance by exact point-triangle distances over a cell grid of triangles.
#include <array>
#include <cstdint>
#include <vector>

#include "core/vec3.hpp"
#include "geometry/triangle_mesh.hpp"

namespace mpdem {

class MeshSolid {
 public:
  // Throws std::invalid_argument when the surface is not closed (an edge used by one triangle or
  // by three or more) or not consistently oriented, naming the count of offending edges.
  explicit MeshSolid(const TriangleMesh& mesh);

  double volume() const { return volume_; }  // m^3, enclosed volume
  Vec3 lo() const { return lo_; }            // m, bounding box
  Vec3 hi() const { return hi_; }
  bool contains(const Vec3& p) const;  // p strictly inside (points on the surface: either)
  // True when no point of the surface is closer to p than d (m).
  bool clear_of_surface(const Vec3& p, double d) const;
  // Distance (m) from p to the nearest point of the surface: the cells in shells of growing
  // Chebyshev distance k around p's cell, until the nearest triangle found is no farther than
  // k cell sizes (no unvisited cell can hold a nearer one). Cost grows with the distance over the
  // cell size (about 4 triangles per cell).
  double distance_to_surface(const Vec3& p) const;
  // m, the nearest point of the surface to p (the point distance_to_surface measures to).
  Vec3 closest_surface_point(const Vec3& p) const;

 private:
  std::vector<std::array<Vec3, 3>> tri_;  // m, triangles
  Vec3 lo_, hi_;
  double volume_ = 0.0;
  // Ray columns over (y, z): CSR lists of triangles whose y-z bounding box meets the column.
  int ny_ = 1, nz_ = 1;
  double hy_ = 1.0, hz_ = 1.0;  // m, column sizes
  std::vector<std::uint32_t> col_start_, col_tri_;
  // Distance cells: CSR lists of triangles whose bounding box meets the cell.
  std::array<int, 3> n_{1, 1, 1};
  double h_ = 1.0;  // m, cell size
  std::vector<std::uint32_t> cell_start_, cell_tri_;
  mutable std::vector<std::uint32_t> stamp_;  // per triangle: last query that tested it
  mutable std::uint32_t query_ = 0;

  int column_y(double y) const;
  int column_z(double z) const;
  int cell(double v, int axis) const;
  std::uint32_t next_query() const;  // a fresh stamp for the triangles a query tests
  template <class F>
  bool each_new_distance2(const Vec3& p, int i, int j, int k, F&& f) const;
  template <class F>
  bool each_new_closest(const Vec3& p, int i, int j, int k, F&& f) const;
  bool ray_crosses(const std::array<Vec3, 3>& t, const Vec3& p) const;
};

}  // namespace mpdem
