#pragma once
// ParaView snapshots as VTK XML UnstructuredGrid (.vtu) files, ASCII with 17 significant digits
// so every double round-trips bit for bit. Files are written atomically (io/atomic_file.hpp).
// Array names, component order and units are listed in docs/output.md.
#include <filesystem>

#include "state/barriers.hpp"
#include "state/particles.hpp"

namespace mpdem {

// One VTK_VERTEX cell per particle, Points = centres (m). PointData: id, radius, material,
// velocity, angular_velocity, force, temperature, charge, orientation (w, x, y, z).
// FieldData "TimeValue" = time (s).
void write_particles_vtu(const std::filesystem::path& file, const Particles& particles, double time);

// One VTK_TRIANGLE per barrier element at its current position (three unshared points each,
// since elements may move with different laws). CellData: id, group, force, moment, pressure,
// normal, velocity, and with activity windows active (1 on, 0 off). FieldData "TimeValue" = time (s).
void write_barriers_vtu(const std::filesystem::path& file, const Barriers& barriers, double time);

}  // namespace mpdem
