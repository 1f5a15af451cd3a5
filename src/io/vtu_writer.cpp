#include "io/vtu_writer.hpp"

#include <fmt/core.h>

#include <array>
#include <cstdint>
#include <ostream>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/atomic_file.hpp"

namespace mpdem {

void open_unstructured_piece(VtkXmlDocument& d, double time, std::size_t points, std::size_t cells,
                             const char* names_prefix, std::span<const std::string> names) {
  d.text("  <UnstructuredGrid>\n"
         "    <FieldData>\n");
  d.field("TimeValue", time);
  // The names beside the indices: one single-tuple Int32 per name, its value the index.
  for (std::size_t k = 0; k < names.size(); ++k) {
    d.field((std::string(names_prefix) + names[k]).c_str(), static_cast<std::int32_t>(k));
  }
  d.text(fmt::format("    </FieldData>\n"
                     "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n",
                     points, cells));
}

void separate_cells(VtkXmlDocument& d, std::size_t count, int per_cell, int vtk_type) {
  d.text("      <Cells>\n");
  const std::size_t n = count * static_cast<std::size_t>(per_cell);
  const auto fill = [&](auto zero) {
    using Index = decltype(zero);
    std::vector<Index> connectivity(n), offsets(count);
    for (std::size_t k = 0; k < n; ++k) connectivity[k] = static_cast<Index>(k);
    for (std::size_t c = 0; c < count; ++c)
      offsets[c] = static_cast<Index>((c + 1) * static_cast<std::size_t>(per_cell));
    const char* type = sizeof(Index) == 4 ? "Int32" : "Int64";
    d.owned_array({"connectivity", type, 0}, connectivity);
    d.owned_array({"offsets", type, 0}, offsets);
  };
  if (n < (std::size_t{1} << 31)) fill(std::int32_t{0});
  else fill(std::int64_t{0});
  d.owned_array({"types", "UInt8", 0}, std::vector<std::uint8_t>(count, static_cast<std::uint8_t>(vtk_type)));
  d.text("      </Cells>\n");
}

void close_unstructured_piece(VtkXmlDocument& d) {
  d.text("    </Piece>\n"
         "  </UnstructuredGrid>\n");
}

namespace {

// The particle point arrays; write_particles_vtu writes each by its index here, in this order.
enum ParticleArray : std::size_t {
  kId,
  kRadius,
  kMaterial,
  kFixed,
  kVelocity,
  kAngularVelocity,
  kForce,
  kTemperature,
  kCharge,
  kOrientation,
  kParticleArrayCount
};
constexpr std::array<VtuArray, kParticleArrayCount> kParticleArrays{{
    {"id", "Int64", 0},                  // -
    {"radius", "Float64", 0},            // m
    {"material", "Int32", 0},            // index into the scene's materials
    {"fixed", "UInt8", 0},               // 1: prescribed motion
    {"velocity", "Float64", 3},          // m/s
    {"angular_velocity", "Float64", 3},  // rad/s
    {"force", "Float64", 3},             // N
    {"temperature", "Float64", 0},       // K
    {"charge", "Float64", 0},            // C
    {"orientation", "Float64", 4},       // unit quaternion (w, x, y, z), body -> world
}};

}  // namespace

std::span<const VtuArray> particle_point_arrays() { return kParticleArrays; }

VtuOptions vtu_options(const Model& model) {
  VtuOptions o{model.params.output.format, {}};
  for (const Material& m : model.materials) o.material_names.push_back(m.name);
  return o;
}

void write_particles_vtu(const std::filesystem::path& file, const Particles& p, double time,
                         const VtuOptions& options) {
  const std::size_t n = p.size();  // the owned particles: ghosts (periodic images) are not written
  const auto owned = [n](const auto& a) { return std::span(a.data(), n); };
  const auto& a = kParticleArrays;  // names, types, units
  VtkXmlDocument d(options.format, "UnstructuredGrid");
  open_unstructured_piece(d, time, n, n, "material:", options.material_names);
  d.text(
      fmt::format("      <PointData Scalars=\"{}\" Vectors=\"{}\">\n", kParticleActiveScalars, kParticleActiveVectors));
  d.array(a[kId], owned(p.id));
  d.array(a[kRadius], owned(p.radius));
  d.array(a[kMaterial], owned(p.material));
  d.array(a[kFixed], owned(p.fixed));
  d.array(a[kVelocity], owned(p.v));
  d.array(a[kAngularVelocity], owned(p.w));
  d.array(a[kForce], owned(p.force));
  d.array(a[kTemperature], owned(p.T));
  d.array(a[kCharge], owned(p.charge));
  d.array(a[kOrientation], owned(p.q));
  d.text("      </PointData>\n"
         "      <Points>\n");
  d.array(kVtuPoints, owned(p.x));  // m, centres
  d.text("      </Points>\n");
  separate_cells(d, n, 1, kVtkVertex);
  close_unstructured_piece(d);
  write_file_atomically(
      file, [&](std::ostream& os) { d.write(os); }, Durability::kill);
}

void write_barriers_vtu(const std::filesystem::path& file, const Barriers& b, double time, VtkFormat format,
                        const ElementLoadView* loads) {
  const std::size_t m = b.size();
  const ElementLoadView own{b.force, b.moment, b.pressure};
  const ElementLoadView& l = loads ? *loads : own;
  if (l.force.size() != m || l.moment.size() != m || l.pressure.size() != m)
    throw std::invalid_argument("write_barriers_vtu: element loads of another size than the barriers");
  VtkXmlDocument d(format, "UnstructuredGrid");
  open_unstructured_piece(d, time, 3 * m, m, "group:", b.group_names);
  d.text("      <CellData Scalars=\"pressure\" Vectors=\"force\">\n");
  d.array({"id", "Int64", 0}, std::span<const std::int64_t>(b.id));        // -
  d.array({"group", "Int32", 0}, std::span<const std::int32_t>(b.group));  // index into group_names
  d.array({"force", "Float64", 3}, l.force);                               // N
  d.array({"moment", "Float64", 3}, l.moment);                             // N m, about the element centre
  d.array({"pressure", "Float64", 0}, l.pressure);                         // Pa
  // Elements with an activity window are all written (at their law's place); 0 marks the
  // switched-off ones, whose loads are zero.
  if (b.timed()) d.array({"active", "UInt8", 0}, std::span<const std::uint8_t>(b.active));
  // A rotating element's normal turns and its velocity varies over it: the one at its centre.
  if (b.rotating()) {
    std::vector<Vec3> normal(m), velocity(m);  // [M] -, m/s
    for (std::size_t e = 0; e < m; ++e) {
      normal[e] = b.current_normal(e);
      velocity[e] = b.surface_velocity(e, b.centre(e));
    }
    d.owned_array({"normal", "Float64", 3}, normal);
    d.owned_array({"velocity", "Float64", 3}, velocity);
  } else {
    d.array({"normal", "Float64", 3}, std::span<const Vec3>(b.normal));      // -, unit
    d.array({"velocity", "Float64", 3}, std::span<const Vec3>(b.velocity));  // m/s
  }
  d.text("      </CellData>\n"
         "      <Points>\n");
  std::vector<Vec3> vertices(3 * m);  // m, current vertex positions
  for (std::size_t e = 0; e < m; ++e)
    for (int k = 0; k < 3; ++k) vertices[3 * e + static_cast<std::size_t>(k)] = b.vertex(e, k);
  d.owned_array(kVtuPoints, vertices);
  d.text("      </Points>\n");
  separate_cells(d, m, 3, kVtkTriangle);
  close_unstructured_piece(d);
  write_file_atomically(
      file, [&](std::ostream& os) { d.write(os); }, Durability::kill);
}

}  // namespace mpdem
