#pragma once
// The container of a dense packing (`mpdem agglomerate`): a sphere, or the solid enclosed by a
// closed triangle surface. Offers its volume, random centres inside it, and the move that puts
// a ball back inside it.
#include <memory>

#include "core/random.hpp"
#include "core/vec3.hpp"
#include "geometry/mesh_solid.hpp"

namespace mpdem {

class PackingContainer {
 public:
  PackingContainer(const Vec3& centre, double radius);                // a sphere (m)
  explicit PackingContainer(std::shared_ptr<const MeshSolid> solid);  // a closed surface's solid

  double volume() const { return volume_; }  // m^3
  Vec3 lo() const { return lo_; }            // m, bounding box
  Vec3 hi() const { return hi_; }
  // A centre drawn uniformly from the container shrunk by `clearance` (m); false when the draw
  // fell outside it (a solid samples its bounding box and rejects).
  bool sample(Rng& rng, double clearance, Vec3& out) const;
  // m, signed distance from p to the surface: positive inside.
  double depth(const Vec3& p) const;
  // Moves p along the surface normal at its nearest surface point until the ball (p, r) lies
  // inside (to rounding); returns by how much it stuck out before (m, 0 when it did not).
  double push_inside(Vec3& p, double r) const;

 private:
  Vec3 centre_;          // m, sphere
  double radius_ = 0.0;  // m, sphere; 0 for a solid
  std::shared_ptr<const MeshSolid> solid_;
  double volume_ = 0.0;
  Vec3 lo_, hi_;
};

}  // namespace mpdem
