#include "io/bond_vtu_writer.hpp"

#include <ostream>
#include <span>

#include "core/atomic_file.hpp"
#include "io/vtk_xml.hpp"
#include "io/vtu_writer.hpp"

namespace mpdem {

void write_bonds_vtu(const std::filesystem::path& file, const BondCells& c, double time, VtkFormat format) {
  const std::size_t n = c.size();
  VtkXmlDocument d(format, "UnstructuredGrid");
  open_unstructured_piece(d, time, 2 * n, n);
  d.text("      <CellData Scalars=\"normal_force\" Vectors=\"shear_force\">\n");
  d.array({"id_i", "Int64", 0}, std::span<const std::int64_t>(c.id_i));
  d.array({"id_j", "Int64", 0}, std::span<const std::int64_t>(c.id_j));
  d.array({"intact", "UInt8", 0}, std::span<const std::uint8_t>(c.intact));
  d.array({"normal_force", "Float64", 0}, std::span<const double>(c.normal_force));        // N
  d.array({"shear_force", "Float64", 3}, std::span<const Vec3>(c.shear_force));            // N
  d.array({"twisting_moment", "Float64", 0}, std::span<const double>(c.twisting_moment));  // N m
  d.array({"bending_moment", "Float64", 3}, std::span<const Vec3>(c.bending_moment));      // N m
  d.array({"sigma_max", "Float64", 0}, std::span<const double>(c.sigma_max));              // Pa
  d.array({"tau_max", "Float64", 0}, std::span<const double>(c.tau_max));                  // Pa
  d.array({"length", "Float64", 0}, std::span<const double>(c.length));                    // m
  d.text("      </CellData>\n"
         "      <Points>\n");
  std::vector<Vec3> ends(2 * n);  // m, each line's two ends
  for (std::size_t b = 0; b < n; ++b) {
    ends[2 * b] = c.from[b];
    ends[2 * b + 1] = c.to[b];
  }
  d.owned_array(kVtuPoints, ends);
  d.text("      </Points>\n");
  separate_cells(d, n, 2, kVtkLine);
  close_unstructured_piece(d);
  write_file_atomically(
      file, [&](std::ostream& os) { d.write(os); }, Durability::kill);
}

}  // namespace mpdem
