#pragma once
// Particle CSV snapshots (docs/output.md "Particle CSV"): every particle at one time, one row each,
// the columns of the particle column table (state/particle_columns.hpp) that the CSV holds, read
// back by io/particle_csv_reader.hpp. Numbers as in io/csv_log.hpp: 17 significant digits,
// integral values as integers.
#include <filesystem>
#include <string>

#include "core/vec3.hpp"
#include "state/particles.hpp"

namespace mpdem {

// The header line without its line break: time, then the table's CSV columns in table order
// (those of CsvRole::periodic, the image counts, only when `periodic`, followed by the unwrapped
// centre).
std::string particle_csv_header(bool periodic);

// Writes all particles at one time as a complete CSV file, atomically, one row per particle in
// ascending id order (whatever their storage order); time in s.
// period [m]: the domain's period along its periodic axes, 0 along the others; with any periodic
// axis the rows add the image counts ix, iy, iz and the unwrapped centre xu, yu, zu (m).
void write_particles_csv(const std::filesystem::path& file, const Particles& particles, double time,
                         const Vec3& period = {});

}  // namespace mpdem
