#pragma once
// Fills a closed surface with overlapping spheres: the members of a clump template (`mpdem clump`,
// docs/tools.md "mpdem clump").
//
// Method: greedy maximum coverage of inscribed spheres on a grid.
//  1. Sample points: a cubic grid of spacing s = (longest bounding-box edge) / resolution, cell
//     centred and symmetric about the bounding box's centre, with as many points per axis as
//     cover the box and have the parity of `resolution` (odd: a point at the middle of every
//     axis); the points inside the solid (ray parity, MeshSolid) stand for its volume.
//  2. Candidates: a sphere at every sample point, with radius its distance to the surface (exact
//     point-triangle distances): the largest sphere there that stays inside the solid.
//  3. Greedy: repeatedly take the candidate whose sphere covers the most sample points not yet
//     covered (ties: the larger radius, then the lower grid index), until `count` spheres are
//     taken or every sample point is covered (then fewer are returned). The gains only fall as
//     points get covered, so stale gains are upper bounds and a lazy priority queue finds the
//     same choice as recomputing every gain at every step.
// Deterministic: the same surface and options give the same spheres, in the order taken. The
// first sphere is the one filling most of the solid (a convex solid's largest inscribed sphere,
// up to the grid), later ones fill the corners and ends. Every sphere lies inside the solid, so
// the template's volume is below the solid's; more spheres and a finer grid bring it closer.
#include <cstddef>
#include <vector>

#include "geometry/triangle_mesh.hpp"
#include "physics/clump_mass.hpp"

namespace mpdem {

struct ClumpFill {
  std::vector<ClumpMember> members;  // m, in the order taken, in the surface's frame
  double spacing = 0.0;              // m, grid spacing s
  std::size_t samples = 0;           // sample points inside the solid
  std::size_t covered = 0;           // of them, inside some member
};

// `mesh` must be a closed, consistently oriented surface (either winding); count >= 1,
// resolution >= 2. Throws std::invalid_argument otherwise, or when no sample point falls inside.
ClumpFill fill_with_spheres(const TriangleMesh& mesh, int count, int resolution);

}  // namespace mpdem
