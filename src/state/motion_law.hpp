#pragma once
// Rigid motion law of a barrier element (physics.md section 7, thesis (97)): the translation
//   u(t) = a t + A sin(w1 t) + B cos(w2 t)
// and, optionally, a rotation about an axis through a point that moves with u (RotationLaw).
// Taken literally, a non-zero B shifts the barrier by B at t = 0 (documented in docs/scene.md).
// The element takes part only in its activity window [active_from, active_until); with a time
// origin `since` > 0 (motion_from = "start") the law runs on max(t - since, 0).
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

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
  double active_from = 0.0;             // s, the element switches on at this time
  double active_until = HUGE_VAL;       // s, ... and off at this one (+inf: never)
  double since = 0.0;                   // s, the law's time origin (rotation->since must match)

  // s, the law's own time; exactly t when since = 0, so a law without origin is unchanged.
  double law_time(double t) const { return since == 0.0 ? t : std::max(t - since, 0.0); }
  Vec3 displacement(double t) const {
    const double s = law_time(t);
    return a * s + A * std::sin(w1 * s) + B * std::cos(w2 * s);
  }
  Vec3 velocity(double t) const {
    if (since != 0.0 && t < since) return {};  // held before the law starts
    const double s = law_time(t);
    return a + A * (w1 * std::cos(w1 * s)) - B * (w2 * std::sin(w2 * s));
  }
  bool is_static() const {
    return norm2(a) == 0.0 && (norm2(A) == 0.0 || w1 == 0.0) && (norm2(B) == 0.0 || w2 == 0.0) &&
           !(rotation && rotation->turns());
  }
  // An activity window other than "always" (the default [0, inf)).
  bool timed() const { return active_from > 0.0 || active_until < HUGE_VAL; }
  // Whether the element takes part at time t: active_from <= t < active_until.
  bool active_at(double t) const { return t >= active_from && t < active_until; }
  // "" when the displacement and velocity stay finite over [0, duration] (their bounds per
  // component |a| T + |A| + |B| and |a| + |A| |w1| + |B| |w2|, the rotation's angle |omega| T), else what
  // overflows; `key` is set to the term to blame ("a", "A", "B", "w1", "w2", "omega").
  std::string limit_problem(double duration, std::string& key) const;
};

}  // namespace mpdem
