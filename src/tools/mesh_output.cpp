// Mesh file output (docs/tools.md "mpdem mesh").
#include "tools/mesh_output.hpp"

#include <ostream>

#include <fmt/format.h>

#include "core/atomic_file.hpp"

namespace mpdem {

void write_mesh_csv(const std::filesystem::path& file, const TriangleMesh& mesh, const std::string& group,
                    std::int64_t first_id) {
  write_file_atomically(file, [&](std::ostream& out) {
    out << "# " << mesh.size() << " triangles written by mpdem mesh; normals (p2 - p1) x (p3 - p1)\n";
    out << "id,x1,y1,z1,x2,y2,z2,x3,y3,z3" << (group.empty() ? "" : ",group") << '\n';
    for (std::size_t t = 0; t < mesh.size(); ++t) {
      const Vec3 a = mesh.corner(t, 0), b = mesh.corner(t, 1), c = mesh.corner(t, 2);
      out << fmt::format("{},{},{},{},{},{},{},{},{},{}", first_id + static_cast<std::int64_t>(t), a.x, a.y, a.z, b.x,
                         b.y, b.z, c.x, c.y, c.z);
      if (!group.empty()) out << ',' << group;
      out << '\n';
    }
  });
}

void write_mesh(const std::filesystem::path& file, const TriangleMesh& mesh, MeshFileFormat format,
                const std::string& group, std::int64_t first_id) {
  if (format == MeshFileFormat::Csv) write_mesh_csv(file, mesh, group, first_id);
  else
    write_stl(file, soup(mesh), format == MeshFileFormat::StlAscii ? StlFormat::Ascii : StlFormat::Binary,
              group.empty() ? "mpdem" : group);
}

}  // namespace mpdem
