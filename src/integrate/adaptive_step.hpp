#pragma once
// Adaptive time-step factor of the staggered fixed-point iteration (physics.md section 10,
// T. I. Zohdi's scheme):
//   Phi_K = (TOL / eps_0)^(1/(p K_D)) / (eps_K / eps_0)^(1/(p K))
// eps_0: error after the first iteration, eps_K: after the last (iteration K), K_D: desired
// iterations, p: convergence exponent. Phi = 1 exactly when the iteration converges at K = K_D
// with eps_K = TOL; Phi > 1 when it converges faster. The factor is clamped to
// [kMinFactor, kMaxFactor] so one step cannot change dt abruptly, and eps_0 = 0 or eps_K = 0
// (converged exactly) gives the largest growth.
#include <algorithm>
#include <cmath>

#include "integrate/step_report.hpp"
#include "model/params.hpp"

namespace mpdem {

inline constexpr double kMinFactor = 0.5;
inline constexpr double kMaxFactor = 2.0;

inline double step_factor(double tol, double eps0, double epsK, int K, int KD, double p) {
  if (!(eps0 > 0.0) || !(epsK > 0.0)) return kMaxFactor;
  const double phi = std::pow(tol / eps0, 1.0 / (p * KD)) / std::pow(epsK / eps0, 1.0 / (p * K));
  return std::clamp(phi, kMinFactor, kMaxFactor);
}

// The most restrictive (smallest) factor over the fields a step integrated.
inline double step_factor(const StepReport& r, const Params& prm) {
  const ToleranceParams& t = prm.tolerance;
  const double tols[kFieldCount] = {t.position, t.velocity, t.rotation, t.angular_velocity, t.temperature};
  const bool active[kFieldCount] = {true, true, prm.analysis.rotation, prm.analysis.rotation, prm.analysis.thermal};
  double f = kMaxFactor;
  for (int k = 0; k < kFieldCount; ++k)
    if (active[k] && r.iterations > 0)
      f = std::min(f, step_factor(tols[k], r.first_error[k], r.last_error[k], r.iterations, prm.time.desired_iterations,
                                  prm.time.p));
  return f;
}

}  // namespace mpdem
