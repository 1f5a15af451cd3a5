#include "io/pvtu_writer.hpp"

#include <fmt/core.h>

#include <ostream>
#include <vector>

#include "core/atomic_file.hpp"
#include "io/vtu_writer.hpp"

namespace mpdem {

namespace {
// "particles/particles_NNNNNN": the stem of every file of snapshot `index`.
std::string stem(std::uint64_t index) { return fmt::format("particles/particles_{:06d}", index); }

// A PDataArray: the declaration of an array the pieces hold, without its values.
void declare(std::ostream& os, const VtuArray& a) {
  os << "      <PDataArray type=\"" << a.type << "\" Name=\"" << a.name << "\"";
  if (a.components > 0) os << " NumberOfComponents=\"" << a.components << "\"";
  os << "/>\n";
}
}  // namespace

std::string particle_pvtu_name(std::uint64_t index) { return stem(index) + ".pvtu"; }

std::string particle_piece_name(std::uint64_t index, int rank) { return fmt::format("{}_p{}.vtu", stem(index), rank); }

void write_particles_piece(const std::filesystem::path& file, const Particles& p, double time,
                           const VtuOptions& options) {
  Particles sorted = p;
  sorted.drop_ghosts();
  sorted.sort_by_id();
  write_particles_vtu(file, sorted, time, options);
}

void write_particles_pvtu(const std::filesystem::path& dir, std::uint64_t index, int pieces) {
  write_file_atomically(
      dir / particle_pvtu_name(index),
      [&](std::ostream& os) {
        os << "<?xml version=\"1.0\"?>\n"
              "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
              "header_type=\"UInt64\">\n"
              "  <PUnstructuredGrid GhostLevel=\"0\">\n"
           << "    <PPointData Scalars=\"" << kParticleActiveScalars << "\" Vectors=\"" << kParticleActiveVectors
           << "\">\n";
        for (const VtuArray& a : particle_point_arrays()) declare(os, a);
        os << "    </PPointData>\n"
              "    <PPoints>\n";
        declare(os, kVtuPoints);  // m, centres
        os << "    </PPoints>\n";
        for (int k = 0; k < pieces; ++k)  // the pieces lie beside the .pvtu
          os << "    <Piece Source=\"" << std::filesystem::path(particle_piece_name(index, k)).filename().string()
             << "\"/>\n";
        os << "  </PUnstructuredGrid>\n"
              "</VTKFile>\n";
      },
      Durability::kill);
}

}  // namespace mpdem
