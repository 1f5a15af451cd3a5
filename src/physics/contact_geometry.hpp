#pragma once
// Contact geometry and kinematics of a particle-particle pair (physics.md sections 5-6,
// thesis (60)-(62)). Pure, allocation-free.
#include <cmath>

#include "core/vec3.hpp"

namespace mpdem {

struct PairGeometry {
  double distance = 0.0;  // m, |x_i - x_j|
  double overlap = 0.0;   // m, |delta| = R_i + R_j - distance (> 0 in contact, (49))
  Vec3 normal;            // -, n_ij = (x_i - x_j)/d, unit, points from j to i
  Vec3 r_Pi;              // m, centre of i -> contact point, -R_i n   (62)
  Vec3 r_Pj;              // m, centre of j -> contact point, +R_j n   (62)
  bool touching = false;  // overlap > 0
};

// Overlap, normal and contact-point arms of spheres (x_i, R_i), (x_j, R_j) (m).
// Coincident centres have no defined normal; +z is used then so nothing becomes NaN.
inline PairGeometry pair_geometry(const Vec3& x_i, double R_i, const Vec3& x_j, double R_j) {
  PairGeometry g;
  const Vec3 d = x_i - x_j;
  g.distance = norm(d);
  g.normal = g.distance > 0.0 ? d / g.distance : Vec3{0.0, 0.0, 1.0};
  g.overlap = R_i + R_j - g.distance;
  g.touching = g.overlap > 0.0;
  g.r_Pi = -R_i * g.normal;
  g.r_Pj = R_j * g.normal;
  return g;
}

// Velocity of i relative to j at the contact point                                 (61)
// v_rel = (v_i + w_i x r_Pi) - (v_j + w_j x r_Pj)   (m/s; w in rad/s, r in m)
inline Vec3 contact_relative_velocity(const Vec3& v_i, const Vec3& w_i, const Vec3& r_Pi, const Vec3& v_j,
                                      const Vec3& w_j, const Vec3& r_Pj) {
  return (v_i + cross(w_i, r_Pi)) - (v_j + cross(w_j, r_Pj));
}

// Particle-barrier: the barrier translates rigidly with u'(t) (97) and does not rotate.
inline Vec3 contact_relative_velocity_barrier(const Vec3& v_i, const Vec3& w_i, const Vec3& r_Pi, const Vec3& u_dot) {
  return (v_i + cross(w_i, r_Pi)) - u_dot;
}

// Normal rate d(delta)/dt = v_rel . n (negative while approaching), used by (49)-(50).
inline double normal_rate(const Vec3& v_rel, const Vec3& n) { return dot(v_rel, n); }

// Tangential part v_t = v_rel - (v_rel . n) n                                    (60)
inline Vec3 tangential_part(const Vec3& v, const Vec3& n) { return v - dot(v, n) * n; }

}  // namespace mpdem
