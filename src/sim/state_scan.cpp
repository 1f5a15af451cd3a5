#include "sim/state_scan.hpp"

#include <cmath>

#include "core/deterministic_sum.hpp"

namespace mpdem {

StateScan scan_state(const Particles& p, const FieldParams& fields, const DomainParams& domain) {
  const Vec3 g = fields.gravity, e = fields.electric;
  const bool electric = norm2(e) > 0.0;  // else the charges are not read
  const auto s = deterministic_sums<6>(p.size(), [&](std::size_t i, std::array<double, 6>& acc) {
    acc[0] += 0.5 * p.mass[i] * norm2(p.v[i]);
    acc[1] += 0.5 * p.inertia[i] * norm2(p.w[i]);
    acc[2] -= p.mass[i] * dot(g, p.x[i]);
    if (electric) acc[3] -= p.charge[i] * dot(e, p.x[i]);
    const bool finite = isfinite(p.x[i]) && isfinite(p.v[i]) && isfinite(p.w[i]) && std::isfinite(p.T[i]);
    acc[4] += finite ? 0.0 : 1.0;
    acc[5] += inside_domain(domain, p.x[i]) ? 0.0 : 1.0;
  });
  return {{s[0], s[1], s[2]}, s[3], static_cast<std::size_t>(s[4]), static_cast<std::size_t>(s[5])};
}

}  // namespace mpdem
