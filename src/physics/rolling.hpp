#pragma once
// Rolling resistance (physics.md section 6, thesis (71)) with a limiter that keeps it from
// reversing the relative rotation within one step. Pure, allocation-free.
#include <algorithm>
#include <cmath>

#include "core/vec3.hpp"

namespace mpdem {

// Effective rotational inertia of the relative rotation w_rel = w_i - w_j when i gets a torque
// T and j gets -T: d(w_rel)/dt = T/I_i + T/I_j = T / I_eff with I_eff = I_i I_j / (I_i + I_j).
// For a barrier (no rotation of its own) use I_eff = I_i.   [kg m^2]
inline double rolling_inertia_pair(double I_i, double I_j) { return I_i * I_j / (I_i + I_j); }

// Rolling-resistance torque on i (j gets the negative)                      (71)   [N m]
//   T = -mu_r r* |f_n| w_rel / |w_rel|,   magnitude limited to |w_rel| I_eff / dt.
// Why the limit: (71) is a constant-magnitude torque whose direction flips with w_rel; applied
// over an explicit step dt it would drive w_rel past zero and make it chatter. With the cap,
// one explicit step changes w_rel by at most T dt / I_eff = -w_rel, i.e. at most stops the
// relative rotation (other torques aside). A pair rolling at steady state thus settles to
// w_rel = 0 instead of oscillating around it. Returns zero when w_rel = 0 (resistance is
// static then, and the contact's tangential spring carries any load).
// w_rel (rad/s), mu_r (-), r_star (m), f_n (N), I_eff (kg m^2), dt (s).
inline Vec3 rolling_resistance_torque(const Vec3& w_rel, double mu_r, double r_star, double f_n, double I_eff,
                                      double dt) {
  if (mu_r <= 0.0) return Vec3{};  // before the square root: most scenes have no rolling friction
  const double w = norm(w_rel);
  if (w == 0.0) return Vec3{};
  const double coulomb = mu_r * r_star * std::abs(f_n);
  const double stop = w * I_eff / dt;
  return (-std::min(coulomb, stop) / w) * w_rel;
}

}  // namespace mpdem
