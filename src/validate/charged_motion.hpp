#pragma once
// Closed-form motion of a point charge in uniform fields, (39)-(42): m dv/dt = q (E' + v x B),
// E' = E + m g / q (gravity acts as an extra uniform field). B along z or zero.
//   v_z(t) = v_z0 + a E'_z t,  a = q/m
//   B = 0:  v_perp(t) = v_perp0 + a E'_perp t
//   B != 0: v_perp = v_d + u, v_d = E' x B / B^2 (drift), and u turns at omega = a B_z:
//           u(t) = exp(-i omega t) u0 in complex notation x + i y.
#include <stdexcept>

#include "core/vec3.hpp"

namespace mpdem::validate {

struct ChargedState {
  Vec3 x;  // m
  Vec3 v;  // m/s
};

// State at time t of a charge q (C) of mass m (kg) started at (x0, v0).
ChargedState charged_motion(const Vec3& x0, const Vec3& v0, double q, double m, const Vec3& E, const Vec3& B,
                            const Vec3& g, double t);

}  // namespace mpdem::validate
