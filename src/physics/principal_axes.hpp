#pragma once
// Principal axes of an inertia tensor (physics.md section 17): the eigen-decomposition of a
// symmetric 3x3 matrix as ascending moments and a proper rotation, made deterministic so that
// equal moments (a sphere, a dumbbell) get reproducible axes and an input that is already
// principal keeps its axes exactly. Used for clump templates; any body's inertia tensor fits.
#include "core/rotation.hpp"  // Mat3
#include "core/vec3.hpp"

namespace mpdem {

struct PrincipalAxes {
  Vec3 moments;  // the eigenvalues, ascending (units of the tensor)
  Mat3 axes{};   // -, rotation principal -> input frame: column k is the unit axis of moments[k], det +1
};

// Moments closer than this (relative to the largest) count as equal unless the caller says more.
inline constexpr double kTieDefault = 1e-12;

// Cyclic Jacobi rotations. Off-diagonal terms below 1e-13 of the largest diagonal one are
// round-off and dropped first (so a diagonal tensor gives a signed permutation, exactly). Then:
// moments ascending; each axis with its largest component positive; moments equal within `tie_rel`
// (relative to the largest) keep the input order of their axes; if the axes are left-handed, two
// equal moments' axes are swapped, else the third axis is negated.
PrincipalAxes principal_axes(const Mat3& tensor, double tie_rel = kTieDefault);

}  // namespace mpdem
