#pragma once
// Region: where generated particles may sit - a box, a cylinder, or the inside of a closed mesh.
// Offers the volume, uniform sampling of sphere centres that keep a clearance from the boundary,
// and the membership test used to accept them.
#include <memory>
#include <string>

#include "core/vec3.hpp"
#include "model/generate_spec.hpp"
#include "geometry/mesh_solid.hpp"
#include "core/random.hpp"

namespace mpdem {

class Region {
 public:
  // Reads the mesh of a Mesh region. Throws InputError (spec.origin, line) for a bad region.
  Region(const RegionSpec& spec, const std::string& origin, std::size_t line);

  double volume() const { return volume_; }  // m^3
  Vec3 lo() const { return lo_; }            // m, bounding box
  Vec3 hi() const { return hi_; }
  // False when no sphere centre keeps `clearance` (m) from the boundary (region too small).
  bool has_room(double clearance) const;
  // A centre drawn uniformly from the region shrunk by `clearance`; false when the draw fell
  // outside it (mesh regions sample their bounding box and reject), which counts as an attempt.
  bool sample(Rng& rng, double clearance, Vec3& out) const;
  // True when the ball of radius `clearance` about p lies inside the region.
  bool holds(const Vec3& p, double clearance) const;

 private:
  RegionSpec spec_;
  double volume_ = 0.0;
  Vec3 lo_, hi_;
  Vec3 u_, v_, w_;       // Cylinder: orthonormal frame, w_ along the axis
  double height_ = 0.0;  // m, Cylinder
  std::shared_ptr<const MeshSolid> solid_;
};

// What is derived from a region's size must be usable (docs/scene.md "Derived limits"); each
// returns "" when it is, else what over- or underflows, for the caller to locate:
//   a box's extent along each axis finite, its volume finite and > 0;
std::string box_size_problem(const Vec3& extent);
//   a cylinder's squared axis length (then `axis_at_fault`), squared radius and volume finite and > 0.
std::string cylinder_size_problem(const Vec3& axis, double radius, bool& axis_at_fault);

// The triangles of a closed mesh file (STL by extension ".stl", else barrier CSV).
TriangleMesh read_region_mesh(const std::filesystem::path& file);

}  // namespace mpdem
