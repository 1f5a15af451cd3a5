#include "io/vtu_writer.hpp"

#include <fmt/core.h>

#include <array>
#include <cstdint>
#include <ostream>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "core/atomic_file.hpp"
#include "state/particle_columns.hpp"

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

// The VTK type of an array's scalars; nullptr for a type the VTU does not write.
template <class T>
constexpr const char* vtk_type() {
  if constexpr (std::is_same_v<T, std::int64_t>) return "Int64";
  else if constexpr (std::is_same_v<T, std::int32_t>) return "Int32";
  else if constexpr (std::is_same_v<T, std::uint8_t>) return "UInt8";
  else if constexpr (std::is_same_v<T, double> || std::is_same_v<T, Vec3> || std::is_same_v<T, Quat>) return "Float64";
  else return nullptr;
}

// A column's declaration: its name, type and components (0 for a scalar: no NumberOfComponents).
template <class C>
constexpr VtuArray declaration(const C& c) {
  using T = typename C::Value;
  return {c.name, vtk_type<T>(), c.components == 1 ? 0 : static_cast<int>(c.components)};
}

// The table's VTU slots are 0 .. n-1, each once, on columns of a type the VTU writes, and one
// column is the Points (3 doubles).
constexpr std::size_t vtu_array_count() {
  std::size_t n = 0;
  for_each_particle_column([&n](const auto& c) { n += c.vtu >= 0 ? 1 : 0; });
  return n;
}
constexpr bool vtu_slots_valid() {
  bool ok = true;
  int points = 0;
  for (std::size_t slot = 0; slot < vtu_array_count(); ++slot) {
    int holders = 0;
    for_each_particle_column([&](const auto& c) { holders += c.vtu == static_cast<int>(slot) ? 1 : 0; });
    ok = ok && holders == 1;
  }
  for_each_particle_column([&](const auto& c) {
    using T = typename std::decay_t<decltype(c)>::Value;
    if (c.vtu >= 0) ok = ok && vtk_type<T>() != nullptr;
    if (c.vtu == kVtuPointsSlot) points += std::is_same_v<T, Vec3> ? 1 : 2;
  });
  return ok && points == 1;
}
static_assert(vtu_slots_valid(), "particle_columns.hpp: VTU slots must be 0 .. n-1, each once, and one Points column");

// The particle point arrays in file order (their slots).
constexpr std::array<VtuArray, vtu_array_count()> particle_arrays_in_slot_order() {
  std::array<VtuArray, vtu_array_count()> out{};
  for_each_particle_column([&out](const auto& c) {
    if (c.vtu >= 0) out[static_cast<std::size_t>(c.vtu)] = declaration(c);
  });
  return out;
}
constexpr auto kParticleArrays = particle_arrays_in_slot_order();

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
  VtkXmlDocument d(options.format, "UnstructuredGrid");
  open_unstructured_piece(d, time, n, n, "material:", options.material_names);
  d.text(
      fmt::format("      <PointData Scalars=\"{}\" Vectors=\"{}\">\n", kParticleActiveScalars, kParticleActiveVectors));
  // Each column by its slot; the table is short, so a scan per slot.
  for (std::size_t slot = 0; slot < kParticleArrays.size(); ++slot)
    for_each_particle_column([&](const auto& c) {
      if (c.vtu == static_cast<int>(slot)) {
        if constexpr (vtk_type<typename std::decay_t<decltype(c)>::Value>() != nullptr)
          d.array(kParticleArrays[slot], owned(p.*c.array));
      }
    });
  d.text("      </PointData>\n"
         "      <Points>\n");
  for_each_particle_column([&](const auto& c) {
    if constexpr (std::is_same_v<typename std::decay_t<decltype(c)>::Value, Vec3>)
      if (c.vtu == kVtuPointsSlot) d.array(kVtuPoints, owned(p.*c.array));  // m, centres
  });
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
