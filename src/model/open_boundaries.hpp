#pragma once
// Open-system boundaries of a scene (docs/scene.md "[[inlet]]" and "[[sink]]"): inlets insert
// particles during the run, sinks take them out. Plain data, read by scene/inlet_reader.cpp and
// acted on between steps by sim/inlets.hpp and sim/sinks.hpp.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "core/vec3.hpp"
#include "model/clump_mix.hpp"
#include "model/generate_spec.hpp"
#include "model/radius_distribution.hpp"

namespace mpdem {

// Where an inlet places its particles. Every shape is reduced to a generator region (Box or
// Cylinder, generate/region.hpp) in a frame: world = origin + a u + b v + c w for a point (a, b, c)
// of the region. A box, a cylinder and a disc face are regions in world coordinates (identity
// frame); a rectangle face is a box [0, |edge1|] x [0, |edge2|] x [0, depth] in the frame of its
// edges and its normal.
struct InsertionVolume {
  std::string shape = "box";                // "box", "cylinder", "disc" or "rect", as given (messages)
  RegionSpec region;                        // the region in frame coordinates (Box or Cylinder)
  Vec3 origin{};                            // m, frame origin
  Vec3 u{1, 0, 0}, v{0, 1, 0}, w{0, 0, 1};  // -, orthonormal frame axes
};

struct InletSpec {
  std::string name;  // prefix of its log columns ("inlet1", ... unless given)
  InsertionVolume volume;
  double mass_rate = 0.0;     // kg/s, > 0 when the inlet is mass driven
  double count_rate = 0.0;    // 1/s, > 0 when it is count driven (exactly one of the two is > 0)
  double start = 0.0;         // s, first insertion time
  std::optional<double> end;  // s, no insertion at or after it (none: the run's time.duration)
  double interval = 0.0;      // s, between insertion times (0: 100 x time.dt)
  // m; with `clump`: the templates' member radii (discrete, equal fractions), for the estimates
  // that go by the inserted spheres' radii (neighbour skin, time step, impact overlap)
  RadiusDistribution radius;
  ClumpMix clump;                // clump templates: the inlet inserts bodies (empty: spheres)
  std::string material;          // material name ("" = the first material)
  Vec3 velocity{};               // m/s, initial velocity of every inserted particle
  double velocity_spread = 0.0;  // m/s, each component + uniform random in [-spread, spread]
  std::uint64_t seed = 1;
  std::size_t max_attempts = 1000;  // random positions tried per particle and insertion time
  std::size_t line = 0;             // line of the [[inlet]] entry in the scene file

  // s, the interval in effect: `interval`, or 100 time steps of `dt` when none is given.
  double interval_or_default(double dt) const { return interval > 0.0 ? interval : 100.0 * dt; }
};

struct SinkSpec {
  std::string name;   // prefix of its log columns ("sink1", ... unless given)
  RegionSpec region;  // Box or Cylinder, world coordinates: particles whose centre is inside go
  std::size_t line = 0;
};

}  // namespace mpdem
