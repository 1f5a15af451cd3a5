// The agglomerate's particle and bond CSVs (docs/tools.md "mpdem agglomerate").
#include <ostream>

#include <fmt/format.h>

#include "core/atomic_file.hpp"
#include "generate/agglomerate.hpp"

namespace mpdem {

void write_agglomerate_particles(const std::filesystem::path& file, const Agglomerate& a, const std::string& material,
                                 double density, const std::string& comment) {
  write_file_atomically(file, [&](std::ostream& out) {
    out << "# " << comment << '\n';
    out << "id,x,y,z,radius" << (material.empty() ? "" : ",material") << (density > 0.0 ? ",density" : "") << '\n';
    // Each number the shortest text that reads back exactly (fmt's default for double).
    const std::string tail = (material.empty() ? "" : "," + material) +
                             (density > 0.0 ? fmt::format(",{}", density) : "");
    for (std::size_t i = 0; i < a.x.size(); ++i)
      out << fmt::format("{},{},{},{},{}", i, a.x[i].x, a.x[i].y, a.x[i].z, a.radius[i]) << tail << '\n';
  });
}

void write_bond_csv(const std::filesystem::path& file, const std::vector<std::array<std::size_t, 2>>& bonds) {
  write_file_atomically(file, [&](std::ostream& out) {
    out << "id_i,id_j\n";
    for (const auto& [i, j] : bonds) out << i << ',' << j << '\n';
  });
}

}  // namespace mpdem
