#pragma once
// Mass properties of a clump template: the union of its member spheres, overlaps counted once
// (physics.md section 17, "Clump templates: mass properties").
//
// Method. Members that overlap no other member (|x_i - x_j| >= r_i + r_j; touching, to 1e-12
// relative, is not overlapping) are summed in closed form: V = 4/3 pi r^3 and, about the
// member's centre, the second moment V r^2 / 5 per axis, moved to the common origin by the
// parallel-axis theorem; their share of the errors is 0. Each connected cluster of overlapping
// members is integrated: along z exactly (a line parallel to z meets each sphere in an interval;
// the intervals are merged and 1, z, z^2 integrated in closed form), across y and x by
// Gauss-Legendre rules on segments between breakpoints, where the integrand stops being smooth:
// in x the spheres' extents, the extents of each pair's intersection circle, the points common
// to three spheres and the crossings of each sphere's z-equator with the other spheres; in y
// (per x) the cross-section circles' extents and their pairwise intersections (less those
// strictly inside another member). On each segment the substitution
// u = (a + b)/2 - (b - a)/2 cos t absorbs the square-root behaviour at the ends (a chord
// ~ sqrt(distance) at a silhouette), so the rules converge exponentially.
//
// Error estimate. The integration runs with n and 2n points per segment (n = 6, 12, 24, 48,
// doubled until both estimates are below 1e-8) and reports the 2n result; the estimate is the
// relative change from n to 2n (conservative: with exponential convergence the 2n result is
// much closer than that), at least a round-off floor of 1e-13. For the principal moments it is
// the Frobenius norm of the change of the inertia tensor over the smallest moment, which bounds
// the change of every eigenvalue (Weyl's inequality).
//
// Principal frame (physics/principal_axes.hpp): the inertia tensor about the centroid by cyclic
// Jacobi rotations; a tensor that is already diagonal keeps the input axes exactly; moments
// equal within the error estimate (or 1e-12) keep the input order of their axes, so degenerate
// moments give deterministic axes (a sphere keeps the input axes; a dumbbell along input y gets
// axis 1 = +y, 2 = z, 3 = x).
#include <vector>

#include "core/rotation.hpp"  // Mat3, Quat
#include "core/vec3.hpp"

namespace mpdem {

struct ClumpMember {  // one sphere of a template
  Vec3 x;             // m, centre in the template (input) frame
  double r = 0.0;     // m, radius
};

// Per unit density (rho = 1 kg/m^3): multiply mass and inertia by the material's density.
struct ClumpMassProperties {
  double volume = 0.0;  // m^3, of the union of the members (overlaps counted once)
  Vec3 centroid;        // m, centre of volume in the input frame
  Mat3 inertia{};       // m^5 (kg m^2 per kg/m^3), inertia tensor about the centroid, input-frame axes
  Vec3 principal;       // m^5, principal moments, ascending I1 <= I2 <= I3
  Quat to_input;        // rotation principal frame -> input frame (unit quaternion, proper rotation, det +1):
                        // a vector d in the principal frame is quat_matrix(to_input) * d in the input frame
  std::vector<ClumpMember> members_principal;  // members re-expressed in the principal frame about the centroid
  double volume_error = 0.0;                   // relative error estimate of `volume` (0 when exact)
  double inertia_error = 0.0;  // relative error estimate of the principal moments (max over the three; 0 when exact)
  bool overlapping = false;    // whether some members overlap (then the values come from the integration)
};

// Throws std::invalid_argument on no members, a radius <= 0 or a non-finite value (the caller turns it into
// file:line:key).
ClumpMassProperties clump_mass_properties(const std::vector<ClumpMember>& members);

}  // namespace mpdem
