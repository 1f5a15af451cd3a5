#pragma once
// Scene summary for `mpdem check` and the start-up warning of `mpdem run`.
#include "model/scene.hpp"

namespace mpdem::cli {

struct TimeStepAdvice {
  double rayleigh = 0.0;         // s, smallest Rayleigh time over the particles
  double hertz_pp = 0.0;         // s, shortest particle-particle Hertz contact at the reference speed
  double hertz_pb = 0.0;         // s, shortest particle-barrier Hertz contact (0 without barriers)
  double reference_speed = 0.0;  // m/s, max(largest initial speed, 1 m/s)
  double recommended = 0.0;      // s, min(0.2 rayleigh, hertz / 50)
};

TimeStepAdvice time_step_advice(const Scene& scene);
void print_summary(const Scene& scene);
// Warns on stderr when time.dt exceeds the recommended step.
void warn_about_time_step(const Scene& scene);

}  // namespace mpdem::cli
