#pragma once
// Particle CSV reader (docs/scene.md "Particle CSV"): a named header row, columns in any order,
// unknown columns are an error, missing optional columns take the material's defaults; a row that
// gives its own material constants gets a variant of its material (model/material_variants.hpp),
// added to the model.
#include <filesystem>

#include "model/scene.hpp"

namespace mpdem {

// Appends the particles of `file` to `out`. `default_material` is the index of the material used
// for rows without a `material` column/value. Throws InputError (file, line, column, expectation).
void read_particle_csv(const std::filesystem::path& file, Model& model, int default_material, Particles& out);

}  // namespace mpdem
