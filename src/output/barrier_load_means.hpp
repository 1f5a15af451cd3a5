#pragma once
// Barrier loads averaged over an output interval (docs/output.md "Barrier loads: means or
// samples"): the time integral of each element's force, moment, pressure, torque about its
// rotation axis and drive power over the accepted steps since the last output, divided by the
// time it spans. Each step contributes its end-of-step loads times its length h, so a load that
// is constant over the interval is its own mean to round-off, and a periodic load sampled
// evenly over whole periods averages to its mean.
#include <vector>

#include "core/vec3.hpp"
#include "core/binary_stream.hpp"
#include "state/barriers.hpp"

namespace mpdem {

// Per-element loads [M]: what the barrier outputs write.
struct BarrierLoads {
  std::vector<Vec3> force;          // N, by the particles on the element
  std::vector<Vec3> moment;         // N m, about the element's centre
  std::vector<double> pressure;     // Pa
  std::vector<double> axis_torque;  // N m, about its rotation axis (0 when it does not turn)
  std::vector<double> drive_power;  // W, put into the particles
};

// The loads of the last evaluation (an instantaneous sample).
BarrierLoads current_loads(const Barriers& b);

class BarrierLoadMeans {
 public:
  // Adds the loads at the end of an accepted step of length h (s).
  void add(const Barriers& b, double h);
  double span() const { return span_; }  // s, time since the last clear()
  // The means over the span; the current loads when nothing was added (the run's first output).
  BarrierLoads mean(const Barriers& b) const;
  void clear();
  void save(BinaryWriter& w) const;
  void restore(BinaryReader& r);

 private:
  double span_ = 0.0;  // s
  BarrierLoads sum_;   // time integrals: N s, N m s, Pa s, N m s, J
};

}  // namespace mpdem
