// Interactions' first pass of an evaluation: the body forces start the force sums
// (interact/body_forces.hpp), the torques and heat flows start at zero.
#include "core/deterministic_sum.hpp"
#include "core/parallel.hpp"
#include "interact/body_forces.hpp"
#include "interact/interactions.hpp"

namespace mpdem {

double Interactions::start_accumulators(Particles& p) const {
  // One pass: the body forces start the force sums, torque and heat start at zero.
  // Without a field beyond gravity only the masses are read, and without heat transfer the heat
  // flows (zero, never written) are not touched: memory traffic is what a pass over 10^5
  // particles costs.
  const BodyForces forces(model_.params.fields);
  const bool thermal = heat_ != nullptr;
  const std::size_t n = p.size();
  if (p.has_bodies()) {
    // Clumps: the body forces act on the bodies (interact/body_sums.hpp), not on their members.
    return deterministic_block_sums<1>(n, [&](std::size_t lo, std::size_t hi, std::array<double, 1>& lost) {
      for (std::size_t i = lo; i < hi; ++i) {
        p.force[i] = p.body[i] == kNoBody ? forces.force(p, i, lost[0]) : Vec3{};
        p.torque[i] = Vec3{};
        if (thermal) p.heat[i] = 0.0;
      }
    })[0];
  }
  if (forces.only_first()) {
#pragma omp parallel if (n > kParallelThreshold)
    start_first_forces(p);
    return 0.0;
  }
  // W, the dissipative entries' power, summed in fixed blocks (independent of the thread count).
  return deterministic_block_sums<1>(n, [&](std::size_t lo, std::size_t hi, std::array<double, 1>& lost) {
    for (std::size_t i = lo; i < hi; ++i) {
      p.force[i] = forces.force(p, i, lost[0]);
      p.torque[i] = Vec3{};
      if (thermal) p.heat[i] = 0.0;
    }
  })[0];
}

void Interactions::start_first_forces(Particles& p) const {
  const BodyForces forces(model_.params.fields);
  const bool thermal = heat_ != nullptr;
  const std::size_t n = p.size();
#pragma omp for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    p.force[i] = forces.first_force(p, i);
    p.torque[i] = Vec3{};
    if (thermal) p.heat[i] = 0.0;
  }
}

}  // namespace mpdem
