#pragma once
// Parallel bonds in the scene file (docs/scene.md "[bonds]"): the [bonds] defaults, the
// [[bonds.pair]] overrides per pair of materials and the bond CSV ([bonds] file, columns
// id_i,id_j) into Params::bonds; and, once the particles are loaded, the listed bonds' ids
// against them.
#include <filesystem>

#include "io/toml_section.hpp"
#include "model/scene.hpp"

namespace mpdem {

// Reads [bonds] and [[bonds.pair]] of the scene's root table into model.params.bonds, and the
// rows of the bond CSV (relative to `dir`, the scene file's folder); the materials must be read
// already. Throws InputError naming file, line and key (or CSV column) for every problem.
void read_bonds(const TomlSection& root, const std::filesystem::path& dir, Model& model);

// After the particles are loaded: every listed bond names two particles that exist, that are not
// members of one clump body, that are not both fixed (a fixed body's members count as fixed) and
// whose materials may be bonded; otherwise an InputError at the bond CSV's line and column.
void check_listed_bonds(const Scene& scene);

}  // namespace mpdem
