#pragma once
// A generator request for the generator tests: `count` spheres of one radius in the box [0, side]^3.
#include <cstddef>

#include "model/generate_spec.hpp"

namespace mpdem::test {

inline GenerateSpec box_spec(double side, std::size_t count, double radius) {
  GenerateSpec s;
  s.region.shape = RegionShape::Box;
  s.region.min = {0, 0, 0};
  s.region.max = {side, side, side};
  s.count = count;
  s.radius.law = RadiusLaw::Constant;
  s.radius.value = radius;
  return s;
}

}  // namespace mpdem::test
