#pragma once
// Rigid motion law of a barrier element (physics.md section 7, thesis (97)): the translation
//   u(t) = a t + A sin(w1 t) + B cos(w2 t)
// and, optionally, a rotation about an axis through a point that moves with u (RotationLaw).
// Taken literally, a non-zero B shifts the barrier by B at t = 0 (documented in docs/scene.md).
#include <cmath>
#include <optional>

#include "core/vec3.hpp"
#include "state/rotation_law.hpp"

namespace mpdem {

struct MotionLaw {
  Vec3 a{};                             // m/s, constant velocity
  Vec3 A{};                             // m, sine amplitude
  double w1 = 0.0;                      // rad/s
  Vec3 B{};                             // m, cosine amplitude
  double w2 = 0.0;                      // rad/s
  std::optional<RotationLaw> rotation;  // none: translation only

  Vec3 displacement(double t) const { return a * t + A * std::sin(w1 * t) + B * std::cos(w2 * t); }
  Vec3 velocity(double t) const { return a + A * (w1 * std::cos(w1 * t)) - B * (w2 * std::sin(w2 * t)); }
  bool is_static() const {
    return norm2(a) == 0.0 && (norm2(A) == 0.0 || w1 == 0.0) && (norm2(B) == 0.0 || w2 == 0.0) &&
           !(rotation && rotation->turns());
  }
};

}  // namespace mpdem
