#include "interact/body_sums.hpp"

#include "core/parallel.hpp"
#include "interact/body_forces.hpp"

namespace mpdem {

double sum_onto_bodies(Particles& p, const FieldParams& fields, bool thermal) {
  Bodies& B = p.bodies;
  B.index_members(p);
  const BodyForces forces(fields);
  const std::size_t n = p.size(), nb = B.size();
  // Each member's force and torque about its body's centre into its slot (particle order: the
  // particle arrays stream), then each body's slots summed in template order (independent of the
  // particle order and the thread count).
  const std::size_t slots = B.index.size();
  B.slot_force.resize(slots);
  B.slot_torque.resize(slots);
  B.slot_heat.resize(thermal ? slots : 0);
#pragma omp parallel for schedule(static) if (n > kParallelThreshold)
  for (std::size_t i = 0; i < n; ++i) {
    if (p.body[i] == kNoBody) continue;
    const std::size_t b = B.owner[i];
    const std::size_t k = B.first[b] + p.member[i];
    B.slot_force[k] = p.force[i];
    B.slot_torque[k] = cross(p.x[i] - B.x[b], p.force[i]) + p.torque[i];
    if (thermal) B.slot_heat[k] = p.heat[i];
  }
  double lost = 0.0;  // W
  for (std::size_t b = 0; b < nb; ++b) {
    Vec3 f = forces.force(B, b, lost), t{};
    double h = 0.0;
    for (std::uint32_t s = B.first[b]; s < B.first[b + 1]; ++s) {
      f += B.slot_force[s];
      t += B.slot_torque[s];
      if (thermal) h += B.slot_heat[s];
    }
    B.force[b] = f;
    B.torque[b] = t;
    B.heat[b] = h;
  }
  return lost;
}

double fixed_body_power(const Particles& p, bool rotation) {
  const Bodies& B = p.bodies;
  double held = 0.0;
  for (std::size_t b = 0; b < B.size(); ++b)
    if (B.fixed[b]) held -= dot(B.force[b], B.v[b]) + (rotation ? dot(B.torque[b], B.w[b]) : 0.0);
  return held;
}

}  // namespace mpdem
