#pragma once
// The step policy of the integrator a scene's [time] section selects.
#include "interact/step_policy.hpp"
#include "integrate/trapezoidal.hpp"
#include "integrate/verlet.hpp"
#include "model/params.hpp"

namespace mpdem {

inline StepPolicy integrator_policy(const Params& params) {
  return params.time.integrator == Integrator::Verlet ? VerletIntegrator::policy()
                                                      : TrapezoidalIntegrator::policy(params);
}

}  // namespace mpdem
