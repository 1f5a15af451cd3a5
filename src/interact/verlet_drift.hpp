#pragma once
// Velocity Verlet's drift, predicted: where the next step's evaluation will see each particle,
// x + dt (v + dt/2 F/m), with the arithmetic and its order of VerletIntegrator's kick and drift
// (no contraction), so a neighbour-list check against these positions checks the very ones the
// evaluation uses.
#include <cstddef>
#include <cstdint>

#include "core/vec3.hpp"

namespace mpdem {

// How many particles i in [lo, hi) the drift takes farther than sqrt(lim2) (m) from x_ref. A fixed
// particle (fixed[i] != 0; `fixed` null: none is) drifts by dt v, the kick leaving it alone.
inline std::size_t drift_beyond(const Vec3* __restrict x, const Vec3* __restrict x_ref, const Vec3* __restrict v,
                                const Vec3* __restrict f, const double* __restrict m,
                                const std::uint8_t* __restrict fixed, std::size_t lo, std::size_t hi, double dt,
                                double lim2) {
  const double half = 0.5 * dt;
  std::size_t beyond = 0;
  if (fixed == nullptr) {  // the plain loop, for the scenes without fixed particles
    for (std::size_t i = lo; i < hi; ++i) {
      const Vec3 x1 = x[i] + dt * (v[i] + (half / m[i]) * f[i]);
      beyond += norm2(x1 - x_ref[i]) > lim2 ? 1 : 0;
    }
    return beyond;
  }
  for (std::size_t i = lo; i < hi; ++i) {
    const Vec3 x1 = x[i] + dt * (v[i] + ((fixed[i] ? 0.0 : half) / m[i]) * f[i]);
    beyond += norm2(x1 - x_ref[i]) > lim2 ? 1 : 0;
  }
  return beyond;
}

}  // namespace mpdem
