#pragma once
// What one evaluation of the forces is asked (Interactions::evaluate): the kernels below the
// interactions need only this, not the interactions themselves.

namespace mpdem {

struct EvalRequest {
  double time = 0.0;    // s, time of the evaluated state (barrier positions follow it)
  double dt = 0.0;      // s, step length, for tangential spring increments (64)
  double phi = 1.0;     // -, weight of the evaluated state's tangential velocity in the increment
  bool commit = false;  // store contact history: the evaluated state is the accepted end of step
  int iteration = 0;    // fixed-point iteration (1, 2, ...) of the step, 0 outside the iteration
};

}  // namespace mpdem
