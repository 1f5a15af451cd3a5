#include "integrate/rigid_bodies.hpp"

#include "core/parallel.hpp"
#include "model/body_members.hpp"
#include "physics/rigid_rotation.hpp"

namespace mpdem {

void bodies_kick_drift(Particles& p, const std::vector<ClumpTemplate>& clumps, double dt, bool rotation) {
  Bodies& B = p.bodies;
  const double half = 0.5 * dt;
  const std::size_t nb = B.size();
#pragma omp parallel for schedule(static) if (nb > kParallelThreshold / 4)
  for (std::size_t b = 0; b < nb; ++b) {
    if (B.fixed[b]) {
      B.x[b] += dt * B.v[b];
      if (rotation) B.q[b] = rotate_by_increment(B.q[b], dt * B.w[b]);
      continue;
    }
    B.v[b] += (half / B.mass[b]) * B.force[b];
    B.x[b] += dt * B.v[b];
    if (!rotation) continue;
    if (spherical_body(B.inertia[b])) {  // w += dt/2 T / I, as a sphere's
      B.w[b] += (half / B.inertia[b].x) * B.torque[b];
      B.q[b] = rotate_by_increment(B.q[b], dt * B.w[b]);
      continue;
    }
    const Vec3 L = angular_momentum(B.q[b], B.inertia[b], B.w[b]) + half * B.torque[b];  // kg m^2/s
    B.q[b] = free_rotation(B.q[b], B.inertia[b], L, dt);
    B.w[b] = angular_velocity(B.q[b], B.inertia[b], L);
  }
  place_members(clumps, p);
}

void bodies_kick(Particles& p, const std::vector<ClumpTemplate>& clumps, double dt, bool rotation) {
  Bodies& B = p.bodies;
  const double half = 0.5 * dt;
  const std::size_t nb = B.size();
#pragma omp parallel for schedule(static) if (nb > kParallelThreshold / 4)
  for (std::size_t b = 0; b < nb; ++b) {
    if (B.fixed[b]) continue;
    B.v[b] += (half / B.mass[b]) * B.force[b];
    if (!rotation) continue;
    if (spherical_body(B.inertia[b])) {  // w += dt/2 T / I, as a sphere's
      B.w[b] += (half / B.inertia[b].x) * B.torque[b];
      continue;
    }
    const Vec3 L = angular_momentum(B.q[b], B.inertia[b], B.w[b]) + half * B.torque[b];  // kg m^2/s
    B.w[b] = angular_velocity(B.q[b], B.inertia[b], L);
  }
  move_members(clumps, p);
}

void bodies_heat(Particles& p, const std::vector<Material>& materials, double dt) {
  Bodies& B = p.bodies;
  for (std::size_t b = 0; b < B.size(); ++b)
    B.T[b] += dt * B.heat[b] / (B.mass[b] * materials[static_cast<std::size_t>(B.material[b])].heat_capacity);
  for (std::size_t b = 0; b < B.size(); ++b)
    for (std::uint32_t s = B.first[b]; s < B.first[b + 1]; ++s) p.T[B.index[s]] = B.T[b];
}

}  // namespace mpdem
