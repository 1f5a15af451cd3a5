#pragma once
// What `mpdem check` prints about cohesion (docs/scene.md "Contact laws", "[liquid_bridge]"): per
// material pair with an adhesive law its pull-off force and, with hysteresis (JKR), how far past
// touching the neck holds; per pair with liquid bridges the bridge's volume, its force at touching
// and its rupture distance; and how far beyond touching the neighbour search then reaches. For
// two spheres of the largest radius of the scene (the pair the reach is sized for).
#include <string>
#include <vector>

#include "model/scene.hpp"

namespace mpdem {

// Empty when no contact of the scene is adhesive or wet.
std::vector<std::string> cohesion_summary_lines(const Scene& scene);

}  // namespace mpdem
