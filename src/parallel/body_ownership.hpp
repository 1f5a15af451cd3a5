#pragma once
// The clumps' bodies over several ranks (docs/parallel.md "Clumps"): a body belongs to the rank
// whose brick holds its centre of mass, and so do all its member spheres, wherever they reach (a
// member may lie beyond the brick's face by up to its distance from the centre); the ghosts show
// them to the neighbours like any sphere. Here: which rank owns a particle, and the bodies' rows
// as bytes for the messages that carry them with their members (migration, gathers).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec3.hpp"
#include "parallel/brick_grid.hpp"
#include "state/particles.hpp"

namespace mpdem {

// m, [N owned] the point whose brick owns each owned particle: its centre, or, for a member
// sphere, its body's centre of mass. Throws std::logic_error when a member's body is not in p.bodies.
std::vector<Vec3> owner_points(const Particles& p);
// mask[i] = 1 when `rank` owns particle i (by owner_points).
std::vector<char> owned_particles(const BrickGrid& grid, const Particles& p, int rank);
// Keeps the particles and bodies that `rank` owns; returns the particles' mask (applied to p).
std::vector<char> keep_owned(const BrickGrid& grid, Particles& p, int rank);

// Appends bodies idx of B to out: a count, then each array's values (Bodies::for_each_array).
void pack_bodies(Bodies& B, std::span<const std::uint32_t> idx, std::vector<std::byte>& out);
// Appends the bodies of one block written by pack_bodies (from bytes at `pos`, advanced past it)
// to B; returns how many. Throws std::runtime_error on a truncated message.
std::size_t unpack_bodies(Bodies& B, std::span<const std::byte> bytes, std::size_t& pos);

}  // namespace mpdem
