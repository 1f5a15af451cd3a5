#include "integrate/health_scan.hpp"

#include <array>
#include <cstdint>

#include "core/deterministic_sum.hpp"
#include "physics/rigid_rotation.hpp"

namespace mpdem {

namespace {

constexpr std::size_t kLanes = 8;

// Particle i's terms of the scan into lane l; with plain pointers, so that the loop over a
// vector's lanes vectorises. The charges are read only with an electric field. In a periodic
// domain the potentials take the unwrapped centre x + image * period (a wrap moves a particle by
// a period, not its energy).
// With kMembers, the member spheres of clumps (body[i] != kNoBody) add no energy (their bodies'
// is scan_bodies'), only their checks. Without kEnergies only the checks' counts (the energy lanes
// stay zero).
template <bool kElectric, bool kPeriodic, bool kMembers = false, bool kEnergies = true>
void scan_range_lanes(const Vec3* __restrict x, const Vec3* __restrict v, const Vec3* __restrict w,
                      const double* __restrict m, const double* __restrict I, const double* __restrict q,
                      const double* __restrict T, const std::array<std::int32_t, 3>* __restrict image, std::size_t lo,
                      std::size_t hi, const FieldParams& fields, const DomainParams& domain,
                      double (&lane)[kScanSums][kLanes], const std::int64_t* __restrict body = nullptr) {
  const Vec3 g = fields.gravity, E = fields.electric;
  const DomainParams d = domain;
  const Vec3 L{d.periodic[0] ? d.max.x - d.min.x : 0.0, d.periodic[1] ? d.max.y - d.min.y : 0.0,
               d.periodic[2] ? d.max.z - d.min.z : 0.0};  // m, the periods
  const auto add = [&](std::size_t i, std::size_t l) {
    Vec3 u = x[i];  // m, unwrapped centre
    if constexpr (kPeriodic) u += Vec3{image[i][0] * L.x, image[i][1] * L.y, image[i][2] * L.z};
    double s = 1.0;  // -, 0 for a member sphere
    if constexpr (kMembers) s = body[i] == kNoBody ? 1.0 : 0.0;
    if constexpr (kEnergies) {
      lane[0][l] += s * (0.5 * m[i] * norm2(v[i]));
      lane[1][l] += s * (0.5 * I[i] * norm2(w[i]));
      lane[2][l] -= s * (m[i] * dot(g, u));
      if constexpr (kElectric) lane[3][l] -= s * (q[i] * dot(E, u));
    }
    lane[4][l] += finite_state(x[i], v[i], w[i], T[i]) ? 0.0 : 1.0;
    lane[5][l] += inside_domain(d, x[i]) ? 0.0 : 1.0;
  };
  std::size_t i = lo;
  for (; i + kLanes <= hi; i += kLanes)
    for (std::size_t l = 0; l < kLanes; ++l) add(i + l, l);
  for (std::size_t l = 0; i < hi; ++i, ++l) add(i, l);
}

template <bool kElectric>
void scan_lanes(const Particles& p, std::size_t lo, std::size_t hi, const FieldParams& fields,
                const DomainParams& domain, double (&lane)[kScanSums][kLanes]) {
  const bool periodic = domain.bounded && domain.any_periodic();
  if (p.has_bodies()) {
    if (periodic)
      scan_range_lanes<kElectric, true, true>(p.x.data(), p.v.data(), p.w.data(), p.mass.data(), p.inertia.data(),
                                              p.charge.data(), p.T.data(), p.image.data(), lo, hi, fields, domain, lane,
                                              p.body.data());
    else
      scan_range_lanes<kElectric, false, true>(p.x.data(), p.v.data(), p.w.data(), p.mass.data(), p.inertia.data(),
                                               p.charge.data(), p.T.data(), p.image.data(), lo, hi, fields, domain,
                                               lane, p.body.data());
    return;
  }
  if (periodic)
    scan_range_lanes<kElectric, true>(p.x.data(), p.v.data(), p.w.data(), p.mass.data(), p.inertia.data(),
                                      p.charge.data(), p.T.data(), p.image.data(), lo, hi, fields, domain, lane);
  else
    scan_range_lanes<kElectric, false>(p.x.data(), p.v.data(), p.w.data(), p.mass.data(), p.inertia.data(),
                                       p.charge.data(), p.T.data(), p.image.data(), lo, hi, fields, domain, lane);
}

// The checks' counts alone: the positions, velocities, spins and temperatures (the periodic
// images and member flags only shape the energies).
void count_lanes(const Particles& p, std::size_t lo, std::size_t hi, const DomainParams& domain,
                 double (&lane)[kScanSums][kLanes]) {
  scan_range_lanes<false, false, false, false>(p.x.data(), p.v.data(), p.w.data(), p.mass.data(), p.inertia.data(),
                                               p.charge.data(), p.T.data(), p.image.data(), lo, hi, FieldParams{},
                                               domain, lane);
}

}  // namespace

void scan_range(const Particles& p, std::size_t lo, std::size_t hi, const FieldParams& fields,
                const DomainParams& domain, std::array<double, kScanSums>& acc, bool energies) {
  double lane[kScanSums][kLanes] = {};
  if (!energies) count_lanes(p, lo, hi, domain, lane);
  else if (norm2(fields.electric) > 0.0) scan_lanes<true>(p, lo, hi, fields, domain, lane);
  else scan_lanes<false>(p, lo, hi, fields, domain, lane);
  for (int k = 0; k < kScanSums; ++k)
    for (std::size_t l = 0; l < kLanes; ++l) acc[k] += lane[k][l];
}

void scan_body(const Bodies& B, std::size_t b, const FieldParams& fields, const DomainParams& domain,
               std::array<double, kScanSums>& acc) {
  Vec3 u = B.x[b];  // m, unwrapped centre of mass
  if (domain.bounded && domain.any_periodic())
    for (int c = 0; c < 3; ++c)
      if (domain.periodic[static_cast<std::size_t>(c)])
        u[c] += B.image[b][static_cast<std::size_t>(c)] * (domain.max[c] - domain.min[c]);
  acc[0] += 0.5 * B.mass[b] * norm2(B.v[b]);
  acc[1] += rotational_energy(B.q[b], B.inertia[b], B.w[b]);
  acc[2] -= B.mass[b] * dot(fields.gravity, u);
  acc[3] -= B.charge[b] * dot(fields.electric, u);
  acc[4] += finite_state(B.x[b], B.v[b], B.w[b], B.T[b]) ? 0.0 : 1.0;
}

void scan_bodies(const Particles& p, const FieldParams& fields, const DomainParams& domain,
                 std::array<double, kScanSums>& acc) {
  for (std::size_t b = 0; b < p.bodies.size(); ++b) scan_body(p.bodies, b, fields, domain, acc);
}

HealthScan scan_state(const Particles& p, const FieldParams& fields, const DomainParams& domain, bool energies) {
  std::array<double, kScanSums> sums = deterministic_block_sums<kScanSums>(
      p.size(), [&](std::size_t lo, std::size_t hi, std::array<double, kScanSums>& acc) {
        scan_range(p, lo, hi, fields, domain, acc, energies);
      });
  if (p.has_bodies()) scan_bodies(p, fields, domain, sums);  // a few bodies: their energies cost nothing
  return scan_from_sums(sums);
}

}  // namespace mpdem
