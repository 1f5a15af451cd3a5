#pragma once
// Reader of the LAMMPS/LIGGGHTS data file of granular atoms (atom_style granular), as used by the
// settled-bed benchmark (docs/benchmark.md): a header with counts and box bounds, then an `Atoms`
// section of `id type diameter density x y z` rows (optional trailing image flags are ignored).
// Plain text only; the benchmark script decompresses .gz files first.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/vec3.hpp"

namespace mpdem {

struct LammpsAtom {
  std::int64_t id = 0;    // atom id, unique
  int type = 1;           // atom type (>= 1)
  double diameter = 0.0;  // m
  double density = 0.0;   // kg/m^3
  Vec3 x;                 // m, centre
};

struct LammpsData {
  Vec3 lo, hi;                    // m, box bounds (xlo ylo zlo, xhi yhi zhi)
  std::size_t atom_types = 0;     // declared number of atom types
  std::vector<LammpsAtom> atoms;  // in file order
};

// Reads `file`. Throws InputError (file, line, what was expected) for a missing or malformed
// header line, an atom count that disagrees with the header, a duplicate id, a non-positive
// diameter or density, or a non-finite coordinate.
LammpsData read_lammps_data(const std::filesystem::path& file);

}  // namespace mpdem
