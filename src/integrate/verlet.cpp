#include "integrate/verlet.hpp"
#include "core/deterministic_sum.hpp"
#include "core/parallel.hpp"

namespace mpdem {

StepReport VerletIntegrator::step(Particles& p, Barriers& b, Interactions& f, double t, double dt) {
  const bool rotation = params_.analysis.rotation;
  const bool thermal = params_.analysis.thermal;
  const std::size_t n = p.size();
  const double half = 0.5 * dt;
#pragma omp parallel for schedule(static) if (n > kParallelThreshold)
  for (std::size_t i = 0; i < n; ++i) {
    p.v[i] += (half / p.mass[i]) * p.force[i];
    p.x[i] += dt * p.v[i];
    if (rotation) {
      p.w[i] += (half / p.inertia[i]) * p.torque[i];
      p.q[i] = rotate_by_increment(p.q[i], dt * p.w[i]);
    }
    if (thermal) p.T[i] += dt * p.heat[i] / (p.mass[i] * p.heat_capacity[i]);
  }
  f.evaluate(p, b, EvalRequest{t + dt, dt, 1.0, true});
  // Second kick, with the health scan of the end state in the same pass (sim/state_scan.hpp).
  const FieldParams& fields = params_.fields;
  const DomainParams& domain = params_.domain;
  StepReport rep;
  rep.scan = scan_from_sums(deterministic_sums<kScanSums>(n, [&](std::size_t i, std::array<double, kScanSums>& acc) {
    p.v[i] += (half / p.mass[i]) * p.force[i];
    if (rotation) p.w[i] += (half / p.inertia[i]) * p.torque[i];
    scan_particle(p, i, fields, domain, acc);
  }));
  rep.scanned = true;
  rep.evaluations = 1;
  return rep;
}

}  // namespace mpdem
