#pragma once
// Particles generated from a scene's `[[particles]] generate = {...}` entry, appended to the
// scene's particle arrays with their material's properties.
#include "model/scene.hpp"
#include "model/generate_spec.hpp"

namespace mpdem {

// Runs the generator and appends its particles to `out`: ids continue after the largest id so
// far; the material is spec.material, else `default_material`; other properties are the
// material's. Throws InputError when the request cannot be met.
void add_generated_particles(const GenerateSpec& spec, const Model& model, int default_material, Particles& out);

}  // namespace mpdem
