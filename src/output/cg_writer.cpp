#include "output/cg_writer.hpp"

#include <fmt/core.h>

#include <array>
#include <span>

#include "core/atomic_file.hpp"
#include "io/vtk_xml.hpp"

namespace mpdem {

namespace {

constexpr const char* kAxis[] = {"x", "y", "z"};

std::span<const double> tensor_values(const std::vector<std::array<double, 9>>& t) {
  return {t.empty() ? nullptr : t.front().data(), 9 * t.size()};
}

}  // namespace

void write_cg_vti(const std::filesystem::path& file, const CgGrid& g, const CgFields& f, double time,
                  VtkFormat format) {
  std::array<int, 3> n{};
  Vec3 origin, spacing;
  for (std::size_t k = 0; k < 3; ++k) {
    const int a = static_cast<int>(k);
    n[k] = g.resolved[k] ? g.cells[k] : 1;
    spacing[a] = (g.max[a] - g.min[a]) / n[k];
    origin[a] = g.min[a] + 0.5 * spacing[a];  // points at the cell centres
  }
  const std::string extent = fmt::format("0 {} 0 {} 0 {}", n[0] - 1, n[1] - 1, n[2] - 1);
  VtkXmlDocument d(format, "ImageData");
  d.text(fmt::format("  <ImageData WholeExtent=\"{}\" Origin=\"{:.17g} {:.17g} {:.17g}\" "
                     "Spacing=\"{:.17g} {:.17g} {:.17g}\">\n    <FieldData>\n",
                     extent, origin.x, origin.y, origin.z, spacing.x, spacing.y, spacing.z));
  d.field("TimeValue", time);
  d.text(fmt::format("    </FieldData>\n    <Piece Extent=\"{}\">\n"
                     "      <PointData Scalars=\"density\" Vectors=\"velocity\">\n",
                     extent));
  d.array({"density", "Float64", 0}, std::span<const double>(f.density));                              // kg/m^3
  d.array({"solid_fraction", "Float64", 0}, std::span<const double>(f.solid_fraction));                // -
  d.array({"number_density", "Float64", 0}, std::span<const double>(f.number_density));                // 1/m^3
  d.array({"velocity", "Float64", 3}, std::span<const Vec3>(f.velocity));                              // m/s
  d.array({"momentum", "Float64", 3}, std::span<const Vec3>(f.momentum));                              // kg/(m^2 s)
  d.array({"stress", "Float64", 9}, tensor_values(f.stress));                                          // Pa
  d.array({"kinetic_stress", "Float64", 9}, tensor_values(f.kinetic_stress));                          // Pa
  d.array({"contact_stress", "Float64", 9}, tensor_values(f.contact_stress));                          // Pa
  d.array({"temperature", "Float64", 0}, std::span<const double>(f.temperature));                      // m^2/s^2
  d.array({"coordination", "Float64", 0}, std::span<const double>(f.coordination));                    // -
  d.array({"boundary_force_density", "Float64", 3}, std::span<const Vec3>(f.boundary_force_density));  // N/m^3
  d.text("      </PointData>\n      <CellData>\n      </CellData>\n    </Piece>\n  </ImageData>\n");
  write_file_atomically(
      file, [&](std::ostream& os) { d.write(os); }, Durability::kill);
}

std::vector<std::string> cg_profile_columns(int axis) {
  std::vector<std::string> c{"time", kAxis[axis], "density", "solid_fraction", "number_density"};
  for (const char* v : {"velocity", "momentum"})
    for (const char* a : kAxis) c.push_back(fmt::format("{}_{}", v, a));
  for (const char* t : {"stress", "kinetic_stress"})
    for (const char* a : kAxis)
      for (const char* b : kAxis) c.push_back(fmt::format("{}_{}{}", t, a, b));
  c.insert(c.end(), {"temperature", "coordination"});
  for (const char* a : kAxis) c.push_back(fmt::format("boundary_force_density_{}", a));
  return c;
}

std::vector<std::vector<double>> cg_profile_rows(const CgGrid& g, const CgFields& f, int axis, double time) {
  std::vector<std::vector<double>> rows(f.size());
  for (std::size_t k = 0; k < f.size(); ++k) {
    std::vector<double>& r = rows[k];
    r = {time, cg_point(g, k)[axis], f.density[k], f.solid_fraction[k], f.number_density[k]};
    for (int a = 0; a < 3; ++a) r.push_back(f.velocity[k][a]);
    for (int a = 0; a < 3; ++a) r.push_back(f.momentum[k][a]);
    r.insert(r.end(), f.stress[k].begin(), f.stress[k].end());
    r.insert(r.end(), f.kinetic_stress[k].begin(), f.kinetic_stress[k].end());
    r.push_back(f.temperature[k]);
    r.push_back(f.coordination[k]);
    for (int a = 0; a < 3; ++a) r.push_back(f.boundary_force_density[k][a]);
  }
  return rows;
}

}  // namespace mpdem
