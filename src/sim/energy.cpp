#include "sim/energy.hpp"

#include "core/deterministic_sum.hpp"

namespace mpdem {

ParticleEnergy particle_energy(const Particles& p, const Vec3& gravity) {
  const auto s = deterministic_sums<3>(p.size(), [&](std::size_t i, std::array<double, 3>& acc) {
    acc[0] += 0.5 * p.mass[i] * norm2(p.v[i]);
    acc[1] += 0.5 * p.inertia[i] * norm2(p.w[i]);
    acc[2] -= p.mass[i] * dot(gravity, p.x[i]);
  });
  return {s[0], s[1], s[2]};
}

}  // namespace mpdem
