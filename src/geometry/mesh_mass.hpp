#pragma once
// Exact mass properties (per unit density) of the solid bounded by a closed triangle surface.
//
// Method: the divergence theorem turns the volume integrals into sums over the triangles; with
// a reference point o (the centre of the vertices' bounding box), triangle (a, b, c) contributes
// the signed tetrahedron (o, a, b, c), whose sign is that of (a-o) . ((b-o) x (c-o)): the signed
// tetrahedra of a closed surface add up to the enclosed solid whatever o is. With u, v, w the
// corners relative to o and V = u . (v x w) / 6 (m^3), the tetrahedron's
//   volume   V,
//   moment   V (u + v + w) / 4                                   (m^4),
//   covariance  integral of x x^T = V / 20 (u u^T + v v^T + w w^T + s s^T),  s = u + v + w   (m^5),
// the closed form of a tetrahedron's second moments (exact for the linear map of the unit
// simplex, whose second moments are (1 + [i = j]) / 120). The sums give the solid's volume,
// centroid and covariance C about o; shifted to the centroid c, C_c = C - V (c - o)(c - o)^T, and
// the inertia tensor is I = tr(C_c) 1 - C_c (m^5; times the density: kg m^2). Exact up to
// rounding for a polyhedron: a triangulated curved surface gives the values of the polyhedron.
// The reference point o keeps the sums free of the cancellation a far-away origin would cause.
// Principal moments and axes: physics/principal_axes.hpp.
//
// Orientation: triangles counter-clockwise seen from outside (outward normals) give a positive
// volume. When the sum is negative (inward normals, as barrier meshes have), every sum changes
// sign together, so the values are taken with the sign flipped and `inward` says so.
//
// The surface must be closed (every edge shared by two triangles, consistently oriented):
// for an open surface the sums depend on o and mean nothing. This function does not check it
// (MeshSolid and closed_surface_problem do).
#include "core/rotation.hpp"
#include "core/vec3.hpp"
#include "geometry/triangle_mesh.hpp"

namespace mpdem {

struct MeshMassProperties {
  double volume = 0.0;  // m^3 (the mass per unit density)
  Vec3 centroid;        // m
  Mat3 inertia{};       // m^5, inertia tensor about the centroid per unit density, mesh axes
  bool inward = false;  // the triangles were wound inward: signs flipped
};

// Throws std::invalid_argument when the mesh has no triangles or encloses no (finite) volume.
MeshMassProperties mesh_mass_properties(const TriangleMesh& mesh);

}  // namespace mpdem
