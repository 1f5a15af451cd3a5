#pragma once
// ParaView's parallel particle snapshots (docs/output.md, "Particle snapshots on several ranks"):
// on N > 1 ranks every rank writes its piece of a snapshot, particles/particles_NNNNNN_pK.vtu
// (K = its rank: its owned particles in id order, in the layout of the one-rank VTU), and rank 0
// the index particles/particles_NNNNNN.pvtu (a PUnstructuredGrid declaring the pieces' arrays and
// listing the N pieces), which particles.pvd lists. Files are written atomically
// (core/atomic_file.hpp).
#include <cstdint>
#include <filesystem>
#include <string>

#include "io/vtu_writer.hpp"
#include "state/particles.hpp"

namespace mpdem {

// File names relative to the output folder; NNNNNN = `index`, the snapshot counter.
std::string particle_pvtu_name(std::uint64_t index);             // particles/particles_NNNNNN.pvtu
std::string particle_piece_name(std::uint64_t index, int rank);  // particles/particles_NNNNNN_pK.vtu

// One rank's piece: the owned particles of p sorted by id, written by write_particles_vtu (same
// arrays, same format); time (s) in its TimeValue field.
void write_particles_piece(const std::filesystem::path& file, const Particles& p, double time,
                           const VtuOptions& options);

// The index of snapshot `index` of output folder `dir`: dir / particle_pvtu_name(index), listing
// the pieces of ranks 0 .. pieces - 1 (in rank order, relative to the .pvtu's folder) and
// declaring the arrays of particle_point_arrays() and the Points. Rank 0 writes it once every
// piece is complete.
void write_particles_pvtu(const std::filesystem::path& dir, std::uint64_t index, int pieces);

}  // namespace mpdem
