// STL writer (docs/tools.md "STL").
#include "io/stl_writer.hpp"

#include <cstdint>
#include <cstring>
#include <ostream>

#include <fmt/format.h>

#include "core/atomic_file.hpp"

namespace mpdem {

namespace {

Vec3 unit_normal(const std::array<Vec3, 3>& t) {
  const Vec3 n = cross(t[1] - t[0], t[2] - t[0]);
  const double l = norm(n);
  return l > 0.0 ? n / l : Vec3{};
}

void put_float(std::ostream& out, double v) {
  const float f = static_cast<float>(v);
  char b[4];
  std::memcpy(b, &f, 4);
  out.write(b, 4);
}

}  // namespace

void write_stl(const std::filesystem::path& file, const std::vector<std::array<Vec3, 3>>& triangles, StlFormat format,
               const std::string& solid_name) {
  write_file_atomically(file, [&](std::ostream& out) {
    if (format == StlFormat::Ascii) {
      out << "solid " << solid_name << '\n';
      for (const auto& t : triangles) {
        const Vec3 n = unit_normal(t);
        out << fmt::format("  facet normal {} {} {}\n    outer loop\n", n.x, n.y, n.z);
        for (const Vec3& p : t) out << fmt::format("      vertex {} {} {}\n", p.x, p.y, p.z);
        out << "    endloop\n  endfacet\n";
      }
      out << "endsolid " << solid_name << '\n';
      return;
    }
    char header[80] = {};
    const std::string h = "binary STL written by mpdem: " + solid_name;
    std::memcpy(header, h.data(), std::min<std::size_t>(h.size(), 80));
    out.write(header, 80);
    const std::uint32_t n = static_cast<std::uint32_t>(triangles.size());
    char count[4];
    std::memcpy(count, &n, 4);
    out.write(count, 4);
    for (const auto& t : triangles) {
      const Vec3 nn = unit_normal(t);
      put_float(out, nn.x);
      put_float(out, nn.y);
      put_float(out, nn.z);
      for (const Vec3& p : t) {
        put_float(out, p.x);
        put_float(out, p.y);
        put_float(out, p.z);
      }
      out.write("\0\0", 2);  // attribute byte count, unused
    }
  });
}

}  // namespace mpdem
