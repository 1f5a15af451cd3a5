#pragma once
// ParaView snapshots as VTK XML UnstructuredGrid (.vtu) files, ASCII with 17 significant digits
// so every double round-trips bit for bit. Files are written atomically (io/atomic_file.hpp).
// Array names, component order and units are listed in docs/output.md.
#include <filesystem>
#include <span>

#include "state/barriers.hpp"
#include "state/particles.hpp"

namespace mpdem {

// The declaration of one DataArray: what a .pvtu index repeats of its pieces' arrays.
struct VtuArray {
  const char* name;
  const char* type;  // VTK type: Float64, Int64, Int32, UInt8
  int components;    // 0: a scalar (written without NumberOfComponents)
};
// The points of every VTU file: m, 3 components.
inline constexpr VtuArray kVtuPoints{"Points", "Float64", 3};

// One VTK_VERTEX cell per particle, Points = centres (m). PointData: id, radius, material, fixed,
// velocity, angular_velocity, force, temperature, charge, orientation (w, x, y, z); the owned
// particles in their array order. FieldData "TimeValue" = time (s).
void write_particles_vtu(const std::filesystem::path& file, const Particles& particles, double time);

// The particle VTU's PointData arrays in file order (its Points: kVtuPoints, the centres), and the
// PointData's active arrays (its Scalars and Vectors attributes).
std::span<const VtuArray> particle_point_arrays();
inline constexpr const char* kParticleActiveScalars = "radius";
inline constexpr const char* kParticleActiveVectors = "velocity";

// One VTK_TRIANGLE per barrier element at its current position (three unshared points each,
// since elements may move with different laws). CellData: id, group, force, moment, pressure,
// normal, velocity, and with activity windows active (1 on, 0 off). FieldData "TimeValue" = time (s).
void write_barriers_vtu(const std::filesystem::path& file, const Barriers& barriers, double time);

}  // namespace mpdem
