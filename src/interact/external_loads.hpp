#pragma once
// Forces and torques a caller adds to particles (the Python module's
// Particles.add_force): held by particle id, added at every evaluation after the field forces
// until replaced or cleared. Their work enters the energy balance (InteractionStats::external_work).
#include <cstdint>
#include <vector>

#include "core/vec3.hpp"
#include "state/particles.hpp"

namespace mpdem {

class ExternalLoads {
 public:
  // Replaces the loads of the particles `id` (others keep theirs); a zero force and torque
  // removes a particle's entry.
  void set(const std::vector<std::int64_t>& id, const std::vector<Vec3>& force, const std::vector<Vec3>& torque);
  void clear();
  bool empty() const { return id_.empty(); }
  // Adds the loads to p.force and p.torque (owned particles; an id no longer present, e.g. a
  // removed particle, is dropped).
  void add_to(Particles& p);
  // W, sum F.v + T.w over the loaded particles (after add_to), with the velocities the particles
  // reach after a kick of `kick` s by their total force and torque (StepPolicy::velocity_lag):
  // the loads' power at the end of the step. Torques count only when rotation is integrated.
  double power(const Particles& p, double kick, bool rotation) const;

 private:
  void locate(const Particles& p);    // index_ for p's current order
  std::vector<std::int64_t> id_;      // [k] particle ids, ascending
  std::vector<Vec3> force_;           // [k] N
  std::vector<Vec3> torque_;          // [k] N m
  std::vector<std::uint32_t> index_;  // [k] storage index in the particles at the last add_to
};

}  // namespace mpdem
