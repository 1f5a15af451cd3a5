#pragma once
// Rigid rotation of a barrier about an axis (docs/scene.md, [[barriers]] motion.rotation):
//   theta(t) = integral from 0 to t of omega(s) ds,
// omega constant, or piecewise linear through the rows of omega_table and held at the first and
// last rows' values outside them. The axis passes through `origin`, which moves with the
// element's translation law (MotionLaw), so x(t) = u(t) + R(theta(t)) (x0 - origin) + origin.
// With a time origin `since` > 0 (motion_from = "start") the law runs on t - since and is at
// rest (theta = 0, omega = 0) before it.
#include <array>
#include <vector>

#include "core/vec3.hpp"

namespace mpdem {

struct RotationLaw {
  Vec3 axis{0.0, 0.0, 1.0};  // -, unit direction; positive omega turns right-handed about it
  Vec3 origin{};             // m, a point of the axis at rest
  double omega = 0.0;        // rad/s, the constant rate (when omega_table is empty)
  // [rows][2]: {t s, omega rad/s}, t strictly ascending; empty: the constant omega.
  std::vector<std::array<double, 2>> omega_table;
  double since = 0.0;  // s, the law's time origin

  double rate(double t) const;   // rad/s, omega(t)
  double angle(double t) const;  // rad, theta(t), the exact integral of the piecewise-linear rate
  bool turns() const;            // some rate is non-zero
  friend bool operator==(const RotationLaw&, const RotationLaw&) = default;
};

}  // namespace mpdem
