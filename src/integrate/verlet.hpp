#pragma once
// Velocity Verlet (kick-drift-kick), one interaction evaluation per step - what LIGGGHTS and
// LAMMPS use. Velocity-dependent forces (damping, Lorentz) see the half-step velocity, and the
// tangential spring increment uses the velocity of the evaluated state (phi = 1 in (64)).
// Temperature is advanced with explicit Euler.
#include <array>
#include <vector>

#include "integrate/health_scan.hpp"
#include "interact/step_policy.hpp"
#include "integrate/step_report.hpp"
#include "model/params.hpp"
#include "model/scene.hpp"
#include "interact/interactions.hpp"

namespace mpdem {

class VerletIntegrator {
 public:
  // The model's parameters, and its materials' heat capacities (looked up every step).
  explicit VerletIntegrator(const Model& model) : model_(model), params_(model.params) {}
  // One commit evaluation per step: the spring increment takes the evaluated velocity (phi = 1),
  // no step-start history; temperatures advance with the start flows only (explicit Euler).
  static StepPolicy policy() { return {1.0, false, 0.0, true, 0.5}; }
  // On entry force/torque/heat hold the rates at the current state; on exit those of the new one.
  StepReport step(Particles& p, Barriers& b, Interactions& f, double t, double dt);

 private:
  const Model& model_;
  const Params& params_;
  // [blocks of core/deterministic_sum.hpp] the second kick's pass: each block's scan sums and
  // count of drifts beyond the next step's limit (J, J, J, J, -, -, -).
  std::vector<std::array<double, kScanSums + 1>> scan_blocks_;
};

}  // namespace mpdem
