#pragma once
// What one integrator step did: evaluations, iterations and the convergence errors per field,
// for the global log, adaptive time stepping and error messages.
#include <array>
#include <cstdint>

#include "integrate/health_scan.hpp"

namespace mpdem {

enum Field : int { kPosition = 0, kVelocity, kRotation, kAngularVelocity, kTemperature, kFieldCount };
inline constexpr std::array<const char*, kFieldCount> kFieldNames{"position", "velocity", "rotation",
                                                                  "angular_velocity", "temperature"};

struct StepReport {
  bool converged = true;
  int iterations = 0;      // fixed-point iterations (0 for explicit steps)
  int evaluations = 0;     // interaction evaluations, including the commit evaluation
  bool two_cycle = false;  // accepted as the midpoint of a two-cycle (a force discontinuity)
  // eps per field after the first iteration (eps_0) and after the last (eps_K), as defined in
  // docs/integrators.md; 0 for fields that are not integrated.
  std::array<double, kFieldCount> first_error{};
  std::array<double, kFieldCount> last_error{};
  int worst_field = kPosition;       // field with the largest eps_K / TOL
  std::int64_t worst_particle = -1;  // id of the particle with the largest last change there
  // The health scan of the end state, when the integrator fused it into its last pass.
  bool scanned = false;
  HealthScan scan;
};

}  // namespace mpdem
