#pragma once
// Sample particles for the output round-trip tests (VTU, CSV), written and read back exactly.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>

#include "core/rotation.hpp"
#include "state/particles.hpp"

namespace mpdem::test {

// Particles whose every output quantity is a distinct, non-round double.
inline Particles make_particles(std::size_t n) {
  Particles p;
  for (std::size_t k = 0; k < n; ++k) {
    const double s = static_cast<double>(k) + 1.0;
    p.add(1'000'000'000'000LL + 7 * static_cast<std::int64_t>(k), static_cast<int>(k % 3), 1e-3 * s / 3.0,
          2500.0 + s / 7.0, {0.1 * s + 1.0 / 3.0, -std::numbers::pi * s, 1e-7 / s}, {s / 9.0, -2.0 / s, 1e3 / 7.0});
    p.w[k] = {std::sqrt(s), -1.0 / (3.0 * s), 1e-300 * s};
    p.q[k] = quat_normalized({std::cos(s), std::sin(s) / 3.0, -0.2 * s, 0.1});
    p.force[k] = {6.02e23 * s / 7.0, -std::exp(-s), 1.0 / 11.0};
    p.T[k] = 293.15 + s / 3.0;
    p.charge[k] = -1.602176634e-19 * s / 3.0;
  }
  return p;
}

}  // namespace mpdem::test
