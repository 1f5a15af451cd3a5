#include "output/contact_writer.hpp"

#include <charconv>
#include <cstdint>
#include <string>
#include <vector>

#include "core/atomic_file.hpp"
#include "io/csv_log.hpp"
#include "io/vtk_xml.hpp"
#include "io/vtu_writer.hpp"

namespace mpdem {

void write_contacts_vtu(const std::filesystem::path& file, std::span<const ContactEntry> contacts, double time,
                        VtkFormat format, bool bodies, bool cohesion) {
  const std::size_t n = contacts.size();
  std::vector<Vec3> points(2 * n), point(n), normal(n), fn(n), ft(n);  // m, m, -, N, N
  std::vector<double> overlap(n), f_mag(n), fn_mag(n);                 // m, N, N
  std::vector<std::int64_t> first(n), second(n), element(n), first_body(n), second_body(n);
  std::vector<std::uint8_t> sliding(n), touching(n), bridge(n);
  for (std::size_t k = 0; k < n; ++k) {
    const ContactEntry& c = contacts[k];
    points[2 * k] = c.centre;
    points[2 * k + 1] = c.centre - c.branch;
    point[k] = c.point;
    normal[k] = c.normal;
    fn[k] = c.normal_force;
    ft[k] = c.tangential_force;
    overlap[k] = c.overlap;
    f_mag[k] = norm(c.normal_force + c.tangential_force);
    fn_mag[k] = norm(c.normal_force);
    first[k] = c.first;
    second[k] = c.second;
    element[k] = c.element;
    first_body[k] = c.first_body;
    second_body[k] = c.second_body;
    sliding[k] = c.sliding ? 1 : 0;
    touching[k] = c.touching ? 1 : 0;
    bridge[k] = c.bridge ? 1 : 0;
  }
  VtkXmlDocument d(format, "UnstructuredGrid");
  open_unstructured_piece(d, time, 2 * n, n);
  d.text("      <CellData Scalars=\"normal_force_magnitude\" Vectors=\"normal_force\">\n");
  d.array({"first", "Int64", 0}, std::span<const std::int64_t>(first));                // -, id
  d.array({"second", "Int64", 0}, std::span<const std::int64_t>(second));              // -, id or -1
  d.array({"element", "Int64", 0}, std::span<const std::int64_t>(element));            // -, barrier element id or -1
  d.array({"point", "Float64", 3}, std::span<const Vec3>(point));                      // m
  d.array({"normal", "Float64", 3}, std::span<const Vec3>(normal));                    // -, unit, towards first
  d.array({"overlap", "Float64", 0}, std::span<const double>(overlap));                // m
  d.array({"normal_force", "Float64", 3}, std::span<const Vec3>(fn));                  // N, on first
  d.array({"tangential_force", "Float64", 3}, std::span<const Vec3>(ft));              // N, on first
  d.array({"force_magnitude", "Float64", 0}, std::span<const double>(f_mag));          // N
  d.array({"normal_force_magnitude", "Float64", 0}, std::span<const double>(fn_mag));  // N
  d.array({"sliding", "UInt8", 0}, std::span<const std::uint8_t>(sliding));            // 1: at the Coulomb limit
  if (bodies) {
    d.array({"first_body", "Int64", 0}, std::span<const std::int64_t>(first_body));    // -, body id or -1
    d.array({"second_body", "Int64", 0}, std::span<const std::int64_t>(second_body));  // -, body id or -1
  }
  if (cohesion) {
    d.array({"touching", "UInt8", 0}, std::span<const std::uint8_t>(touching));  // 1: a contact law acts
    d.array({"bridge", "UInt8", 0}, std::span<const std::uint8_t>(bridge));      // 1: a liquid bridge acts
  }
  d.text("      </CellData>\n      <Points>\n");
  d.array(kVtuPoints, std::span<const Vec3>(points));  // m: first's centre, then the other end
  d.text("      </Points>\n");
  separate_cells(d, n, 2, kVtkLine);
  close_unstructured_piece(d);
  write_file_atomically(
      file, [&](std::ostream& os) { d.write(os); }, Durability::kill);
}

void write_contacts_csv(const std::filesystem::path& file, std::span<const ContactEntry> contacts, double time,
                        bool bodies, bool cohesion) {
  write_file_atomically(
      file,
      [&](std::ostream& os) {
        std::string line = "time,first,second,element,px,py,pz,nx,ny,nz,overlap,fnx,fny,fnz,ftx,fty,ftz,sliding";
        if (bodies) line += ",first_body,second_body";
        line += cohesion ? ",touching,bridge\n" : "\n";
        for (const ContactEntry& c : contacts) {
          const double v[] = {time,
                              static_cast<double>(c.first),
                              static_cast<double>(c.second),
                              static_cast<double>(c.element),
                              c.point.x,
                              c.point.y,
                              c.point.z,
                              c.normal.x,
                              c.normal.y,
                              c.normal.z,
                              c.overlap,
                              c.normal_force.x,
                              c.normal_force.y,
                              c.normal_force.z,
                              c.tangential_force.x,
                              c.tangential_force.y,
                              c.tangential_force.z,
                              c.sliding ? 1.0 : 0.0};
          for (std::size_t k = 0; k < std::size(v); ++k) {
            if (k) line += ',';
            append_csv_number(line, v[k]);
          }
          if (bodies)
            for (const std::int64_t b : {c.first_body, c.second_body}) {
              char buf[24];  // an id as an integer: a double would round ids beyond 2^53
              line += ',';
              line.append(buf, std::to_chars(buf, buf + sizeof buf, b).ptr);
            }
          if (cohesion) {
            line += c.touching ? ",1" : ",0";
            line += c.bridge ? ",1" : ",0";
          }
          line += '\n';
          if (line.size() > (1u << 16)) {
            os << line;
            line.clear();
          }
        }
        os << line;
      },
      Durability::kill);
}

}  // namespace mpdem
