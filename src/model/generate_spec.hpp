#pragma once
// GenerateSpec: what `mpdem generate` and a scene's `[[particles]] generate = {...}` ask for -
// a region, a radius distribution, how many (a count or a solid fraction), a seed, a minimum gap
// and an initial velocity. Plain data; read by src/scene/generate_spec_reader.cpp and the CLI.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "core/vec3.hpp"
#include "model/radius_distribution.hpp"

namespace mpdem {

enum class RegionShape { Box, Cylinder, Mesh };

struct RegionSpec {
  RegionShape shape = RegionShape::Box;
  Vec3 min{}, max{};           // m, Box: opposite corners
  Vec3 base{};                 // m, Cylinder: centre of the base disc
  Vec3 axis{0.0, 0.0, 1.0};    // m, Cylinder: base centre -> top centre (its length is the height)
  double radius = 0.0;         // m, Cylinder
  std::filesystem::path mesh;  // Mesh: closed surface, STL or barrier CSV
};

// How generated clump bodies are kept apart (docs/scene.md "Generated bodies").
enum class BodyPlacement {
  Bounding,  // by their bounding spheres (any orientation fits)
  Members,   // each candidate's members tested against the placed members (denser)
};

struct GenerateSpec {
  RegionSpec region;
  RadiusDistribution radius;
  std::size_t count = 0;        // particles; 0 = fill to solid_fraction instead
  double solid_fraction = 0.0;  // -, target sum(4/3 pi r^3) / region volume
  std::uint64_t seed = 1;
  double gap = 0.0;                   // m, minimum surface distance between particles and to the boundary
  std::string material;               // written to the CSV `material` column ("" = column left out)
  std::optional<Vec3> velocity;       // m/s, the same initial velocity for all
  double speed = 0.0;                 // m/s, > 0: random directions with this magnitude instead
  bool fixed = false;                 // the particles keep their initial velocity (Particles::fixed)
  std::size_t max_attempts = 100000;  // random positions tried per particle before giving up
  BodyPlacement placement = BodyPlacement::Bounding;  // clump bodies only (`placement` key)
  std::string origin = "generate";                    // file (or "generate") named by error messages
  std::size_t line = 0;                               // line in `origin`, 0 = none
};

}  // namespace mpdem
