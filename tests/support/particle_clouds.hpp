#pragma once
// Particle sets for the neighbour-search tests: dense Gaussian clusters, a uniform box with a far
// outlier (radii in [kR0, 5 kR0]), and random displacements of every particle.
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include "core/vec3.hpp"

namespace mpdem::test {

inline constexpr double kR0 = 1e-3;  // m, smallest radius of the test sets

struct Cloud {
  std::vector<Vec3> x;    // m
  std::vector<double> r;  // m
};

// Radii uniform in [kR0, 5 kR0] (ratio 1:5).
inline double random_radius(std::mt19937_64& rng) { return std::uniform_real_distribution<double>(kR0, 5 * kR0)(rng); }

// N particles in a few tight Gaussian clusters (dense: many pairs per particle).
inline Cloud clustered(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 0.01);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  std::vector<Vec3> centres(5);
  for (auto& c : centres) c = {u(rng), u(rng), u(rng)};
  Cloud c;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& k = centres[i % centres.size()];
    c.x.push_back({k.x + g(rng), k.y + g(rng), k.z + g(rng)});
    c.r.push_back(random_radius(rng));
  }
  return c;
}

// N-1 particles uniform in a box of side `box` and one outlier `outlier` m away along x.
inline Cloud spread(std::size_t n, double box, unsigned seed, double outlier = 1e4) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, box);
  Cloud c;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    c.x.push_back({u(rng), u(rng), u(rng)});
    c.r.push_back(random_radius(rng));
  }
  c.x.insert(c.x.begin() + static_cast<std::ptrdiff_t>(n / 2), Vec3{outlier, -3.0, 2.0});
  c.r.insert(c.r.begin() + static_cast<std::ptrdiff_t>(n / 2), 5 * kR0);
  return c;
}

// Moves every particle by a random vector of length < max_step.
inline std::vector<Vec3> jiggle(const std::vector<Vec3>& x, double max_step, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> y = x;
  for (auto& p : y) {
    Vec3 d{g(rng), g(rng), g(rng)};
    d = d * (max_step * u(rng) / norm(d));
    p += d;
  }
  return y;
}

}  // namespace mpdem::test
