#pragma once
// Whether a barrier triangle passes through a generator region (a [[particles]] generate entry):
// the generator places particles without regard to barriers, so such a wall cuts through them.
// A wall on the region's boundary (a container filled to its walls) is not a crossing.
#include <array>
#include <memory>
#include <string>

#include "core/vec3.hpp"
#include "model/generate_spec.hpp"
#include "generate/region.hpp"

namespace mpdem {

class RegionProbe {
 public:
  // Reads the mesh of a mesh region; throws InputError as Region does.
  explicit RegionProbe(const GenerateSpec& spec);

  // True when some point of triangle t lies inside the region deeper than `depth` (m, >= 0) from
  // its boundary (beyond a rounding tolerance). Exact for boxes and cylinders; for mesh regions the
  // triangle's part inside the region's bounding box is sampled at 1/32 of the box's diagonal.
  bool crossed_by(const std::array<Vec3, 3>& t, double depth) const;

  std::string description() const;  // "box from (..) to (..)", for messages

 private:
  RegionSpec spec_;
  Vec3 lo_, hi_;    // m, bounding box
  Vec3 u_, v_, w_;  // Cylinder: orthonormal frame, w_ along the axis
  double height_ = 0.0;
  double tolerance_ = 0.0;  // m, rounding allowance on the depth
  std::unique_ptr<Region> mesh_;
};

}  // namespace mpdem
