#pragma once
// Scene summary for `mpdem check`, the start-up warning of `mpdem run`, and how both print the
// problems of the checks before the run (check/scene_checks.hpp).
#include "check/impact_overlap.hpp"
#include "check/scene_problem.hpp"
#include "model/scene.hpp"

namespace mpdem::cli {

struct TimeStepAdvice {
  double rayleigh = 0.0;    // s, smallest Rayleigh time over the particles under a Hertz law (0: none)
  double contact_pp = 0.0;  // s, shortest particle-particle contact (0 without particles)
  double contact_pb = 0.0;  // s, shortest particle-barrier contact (0 without barriers)
  bool hertz = false;   // some contact uses an elastic (Hertz-like, Law::kElastic) law: its time at the reference speed
  bool linear = false;  // some contact uses a law of constant stiffness (linear): pi sqrt(m*/k_n), any speed
  double reference_speed = 0.0;  // m/s, max(expected impact speed, 1 m/s)
  ImpactSpeed impact;            // the expected impact speed and what sets it
  double viscous = 0.0;          // s, shortest relaxation time m*/c of a viscous liquid bridge (0: none)
  double bond = 0.0;             // s, smallest bond time step 2/omega at t = 0 (physics.md 22; 0: no bond)
  double recommended = 0.0;      // s, min(0.2 rayleigh, contact / 50, 0.5 viscous, bond / 50)
};

TimeStepAdvice time_step_advice(const Scene& scene);
// The scene's parts (particles, materials, barriers, inlets, sinks, coarse grain, outputs), the
// time step and its recommendation, on stdout.
void print_summary(const Scene& scene);
// The summary's lines for inlets, sinks, coarse-grained fields and outputs (summary_entries.cpp).
void print_entries(const Scene& scene);
// Warns on stderr when time.dt exceeds the recommended step; returns whether it did.
bool warn_about_time_step(const Scene& scene);
// Prints every problem on stderr as "error: " or "warning: " and its location. for_run: only the
// problems that would stop the run are errors, the others warn. Returns how many were errors.
std::size_t print_problems(const SceneProblems& problems, bool for_run);

}  // namespace mpdem::cli
