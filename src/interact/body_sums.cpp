#include "interact/body_sums.hpp"

#include "core/parallel.hpp"
#include "interact/body_forces.hpp"

namespace mpdem {

double sum_onto_bodies(Particles& p, const FieldParams& fields, bool thermal) {
  Bodies& B = p.bodies;
  B.index_members(p);
  const BodyForces forces(fields);
  double lost = 0.0;  // W
  for (std::size_t b = 0; b < B.size(); ++b) {
    Vec3 f = forces.force(B, b, lost), t{};
    double h = 0.0;
    for (std::uint32_t s = B.first[b]; s < B.first[b + 1]; ++s) {
      const std::size_t i = B.index[s];
      f += p.force[i];
      t += cross(p.x[i] - B.x[b], p.force[i]) + p.torque[i];
      if (thermal) h += p.heat[i];
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
