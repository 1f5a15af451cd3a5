#pragma once
// StepPolicy: what an integrator needs from the interactions, declared by the integrator
// (TrapezoidalIntegrator::policy, VerletIntegrator::policy) so that the interactions never ask
// which integrator runs.
namespace mpdem {

struct StepPolicy {
  // -, weight of the end-of-step tangential velocity in the spring increment (64).
  double phi = 1.0;
  // Keep each contact's step-start history (tangential velocity, relative rotation, the first
  // iteration's stick/slip decisions): the trapezoidal rule's increment needs it.
  bool step_start = false;
  // -, weight of the end-of-step heat flows when the step's heat is booked (the start flows
  // weigh 1 - heat_weight), matching how the integrator advances the temperatures.
  double heat_weight = 0.0;
  // The step evaluates the interactions once, at x + dt (v + dt/2 F/m) with the step-start
  // x, v, F (velocity Verlet's drift), so prepare_step can check the neighbour lists against those
  // very positions and that evaluation need not scan the particles again.
  bool drift_known = false;
  // -, the committed evaluation sees each particle's velocity velocity_lag x dt x F/m before its
  // end-of-step value (velocity Verlet: 1/2, its second half kick follows the evaluation), which
  // the power of loads acting at the end of the step needs.
  double velocity_lag = 0.0;
};

}  // namespace mpdem
