#pragma once
// ParaView snapshots as VTK XML UnstructuredGrid (.vtu) files in the [output] format
// (io/vtk_xml.hpp: ASCII with 17 significant digits, raw or zlib-compressed appended binary;
// every double round-trips bit for bit in each). Files are written atomically
// (core/atomic_file.hpp). Array names, component order and units are listed in docs/output.md.
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "io/vtk_xml.hpp"
#include "model/scene.hpp"
#include "state/barriers.hpp"
#include "state/particles.hpp"

namespace mpdem {

struct VtuOptions {
  VtkFormat format = VtkFormat::Binary;
  // material index -> name: FieldData "material:NAME" = index beside the indices (one Int32
  // array per material: meshio cannot read VTK string arrays)
  std::vector<std::string> material_names;
};

// The parts every UnstructuredGrid file of mpdem shares, in file order. open_unstructured_piece:
// <UnstructuredGrid>, FieldData "TimeValue" = time (s) and one Int32 "PREFIX NAME" = index per
// name (the names beside the indices), <Piece> with the counts. separate_cells: the <Cells> of
// `count` cells of one VTK type that each use `per_cell` consecutive points of their own; Int32
// indices (half the bytes to write and compress) while they fit. close_unstructured_piece: the
// closing tags.
void open_unstructured_piece(VtkXmlDocument& d, double time, std::size_t points, std::size_t cells,
                             const char* names_prefix = "", std::span<const std::string> names = {});
void separate_cells(VtkXmlDocument& d, std::size_t count, int per_cell, int vtk_type);
inline constexpr int kVtkVertex = 1;  // VTK cell types (vtkCellType.h)
inline constexpr int kVtkLine = 3;
inline constexpr int kVtkTriangle = 5;
void close_unstructured_piece(VtkXmlDocument& d);

// The scene's [output] format and its material names.
VtuOptions vtu_options(const Model& model);

// One VTK_VERTEX cell per particle, Points = centres (m). PointData: id, radius, material, fixed,
// velocity, angular_velocity, force, temperature, charge, orientation (w, x, y, z); the owned
// particles in their array order. FieldData "TimeValue" = time (s), "material:NAME" = index.
void write_particles_vtu(const std::filesystem::path& file, const Particles& particles, double time,
                         const VtuOptions& options = {});

// The particle VTU's PointData arrays in file order (its Points: kVtuPoints, the centres), and the
// PointData's active arrays (its Scalars and Vectors attributes).
std::span<const VtuArray> particle_point_arrays();
inline constexpr const char* kParticleActiveScalars = "radius";
inline constexpr const char* kParticleActiveVectors = "velocity";

// One VTK_TRIANGLE per barrier element at its current position (three unshared points each,
// since elements may move with different laws). CellData: id, group, force, moment, pressure,
// normal, velocity, and with activity windows active (1 on, 0 off). FieldData "TimeValue" = time (s),
// "group:NAME" = group index.
// loads: the element loads to write instead of the barriers' own (each span [M]; interval means).
struct ElementLoadView {
  std::span<const Vec3> force;       // N
  std::span<const Vec3> moment;      // N m, about the element centre
  std::span<const double> pressure;  // Pa
};
void write_barriers_vtu(const std::filesystem::path& file, const Barriers& barriers, double time,
                        VtkFormat format = VtkFormat::Binary, const ElementLoadView* loads = nullptr);

}  // namespace mpdem
