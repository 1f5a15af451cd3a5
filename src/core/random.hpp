#pragma once
// Rng: the generator's random source. std::mt19937_64 produces the same 64-bit sequence on every
// standard library, but std::*_distribution does not; so the variates used by `mpdem generate`
// are derived here, making a seed give the same particles everywhere.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

#include "core/vec3.hpp"

namespace mpdem {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}

  // Uniform in [0, 1): the top 53 bits of one draw, so every double of the grid is equally likely.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

  // Standard normal by Marsaglia's polar method (the second variate is discarded: simpler state).
  double normal() {
    for (;;) {
      const double u = 2.0 * uniform() - 1.0, v = 2.0 * uniform() - 1.0;
      const double s = u * u + v * v;
      if (s > 0.0 && s < 1.0) return u * std::sqrt(-2.0 * std::log(s) / s);
    }
  }

  // Direction uniform on the unit sphere (uniform z and azimuth: Archimedes' hat-box theorem).
  Vec3 unit_vector() {
    const double z = 2.0 * uniform() - 1.0;
    const double phi = 2.0 * 3.14159265358979323846 * uniform();
    const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {s * std::cos(phi), s * std::sin(phi), z};
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace mpdem
