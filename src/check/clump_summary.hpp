#pragma once
// What `mpdem check` prints about the [[clump]] templates (docs/scene.md "Clumps"): per template
// its members, volume, mass, principal moments, the integration's error estimates and the
// overrides, so that a user sees what the run will use before it starts.
#include <string>
#include <vector>

#include "model/scene.hpp"

namespace mpdem {

// The density a template's bodies get: that of the material of the first [[particles]] entry
// with `clump = "name"` (its index in model.materials), else of the first [[inlet]] with it, or -1
// when no entry uses the template.
int clump_material(const Scene& scene, const std::string& name);

// One header line ("clumps: 2 templates, 10 bodies, 40 member spheres") and one line per
// template; empty when the scene defines none.
std::vector<std::string> clump_summary_lines(const Scene& scene);

}  // namespace mpdem
