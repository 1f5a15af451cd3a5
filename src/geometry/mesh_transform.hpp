#pragma once
// Placing a triangle mesh: scale, rotation about the axes, translation (STL barriers, mesh tools).
#include "core/vec3.hpp"
#include "geometry/triangle_mesh.hpp"

namespace mpdem {

// Rotation about x, then y, then z by the angles in degrees (the order of docs/scene.md).
Vec3 rotate_xyz_deg(const Vec3& p, const Vec3& deg);
// p -> rotate(scale p) + translate for every vertex.
void transform_mesh(TriangleMesh& mesh, double scale, const Vec3& rotate_deg, const Vec3& translate);

}  // namespace mpdem
