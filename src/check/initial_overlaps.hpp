#pragma once
// Overlaps present at t = 0, measured as the run's checks.max_overlap test measures them after
// each step: particle-particle overlap / smaller radius, particle-barrier overlap / radius (the
// barrier surface offset by half its thickness). Found with the engine's neighbour machinery (a
// Verlet list without skin, the barrier broad phase and contact detection), O(N log M).
#include <cstddef>
#include <vector>

#include "state/barriers.hpp"
#include "state/particles.hpp"

namespace mpdem {

// With checks.max_overlap = 0 (check off) initial overlaps deeper than this still warn.
inline constexpr double kInitialOverlapWarning = 0.05;

struct PairOverlap {
  std::size_t i = 0, j = 0;  // particle indices, i < j
  double overlap = 0.0;      // m, R_i + R_j - |x_i - x_j|
  double ratio = 0.0;        // -, overlap / min(R_i, R_j)
};

struct BarrierOverlap {
  std::size_t i = 0;     // particle index
  std::size_t e = 0;     // barrier element index
  double overlap = 0.0;  // m, R_i + t_b/2 - distance to the triangle
  double ratio = 0.0;    // -, overlap / R_i
};

// Pairs / particle-element contacts whose ratio exceeds min_ratio, deepest first (ties by index).
std::vector<PairOverlap> particle_overlaps(const Particles& p, double min_ratio);
std::vector<BarrierOverlap> barrier_overlaps(const Particles& p, const Barriers& b, double min_ratio);

}  // namespace mpdem
