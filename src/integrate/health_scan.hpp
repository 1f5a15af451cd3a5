#pragma once
// The health scan: one pass over the particles after every step for the run's checks:
// energies for the energy balance, non-finite states, particles outside the
// domain. Counting only - the caller looks for the culprits in the rare case there are any.
// Sums are thread-count independent.
#include <array>
#include <cmath>
#include <cstddef>

#include "model/params.hpp"
#include "integrate/energy_balance.hpp"
#include "state/particles.hpp"

namespace mpdem {

// True when x lies in the closed box of a bounded domain (always true when unbounded); a
// periodic axis never leaves (positions are wrapped at the next list rebuild).
// & and | rather than && and ||: no branch, so the scan's loop vectorises.
inline bool inside_domain(const DomainParams& d, const Vec3& x) {
  return (!d.bounded) | ((d.periodic[0] | ((x.x >= d.min.x) & (x.x <= d.max.x))) &
                         (d.periodic[1] | ((x.y >= d.min.y) & (x.y <= d.max.y))) &
                         (d.periodic[2] | ((x.z >= d.min.z) & (x.z <= d.max.z))));
}

// True when a particle's position, velocity, spin and temperature are all finite.
inline bool finite_state(const Vec3& x, const Vec3& v, const Vec3& w, double T) {
  return isfinite(x) & isfinite(v) & isfinite(w) & std::isfinite(T);
}
inline bool finite_state(const Particles& p, std::size_t i) { return finite_state(p.x[i], p.v[i], p.w[i], p.T[i]); }

struct HealthScan {
  ParticleEnergy energy;      // J, kinetic, rotational, gravitational
  double electric = 0.0;      // J, potential in the uniform electric field, -sum q E.x
  std::size_t nonfinite = 0;  // particles with a non-finite x, v, w or T
  std::size_t outside = 0;    // particles outside the domain (0 when it is unbounded)
};

// energies = false: the particles' energy sums are skipped and stay zero ([checks] energy_ledger =
// false books no balance); the counts are the same.
HealthScan scan_state(const Particles& p, const FieldParams& fields, const DomainParams& domain, bool energies = true);

inline constexpr int kScanSums = 6;  // kinetic, rotational, potential, electric, non-finite, outside

// The scan of particles [lo, hi) added to acc (the sums in HealthScan order), summed in 8
// interleaved lanes (a fixed order, so still independent of the thread count) so that the loop
// vectorises. Integrators fuse it into their last pass over a block of particles (one pass less
// of memory traffic per step), with deterministic_block_sums<kScanSums> as in scan_state().
// energies as in scan_state().
void scan_range(const Particles& p, std::size_t lo, std::size_t hi, const FieldParams& fields,
                const DomainParams& domain, std::array<double, kScanSums>& acc, bool energies = true);

// The clump bodies' energies (kinetic, rotational, potential: their members add none in
// scan_range) and non-finite states added to acc; serial, in body order. The potentials take the
// unwrapped centre of mass x + image * period in a periodic domain.
void scan_bodies(const Particles& p, const FieldParams& fields, const DomainParams& domain,
                 std::array<double, kScanSums>& acc);
// Body b's terms alone (what a removed body takes along).
void scan_body(const Bodies& B, std::size_t b, const FieldParams& fields, const DomainParams& domain,
               std::array<double, kScanSums>& acc);

inline HealthScan scan_from_sums(const std::array<double, kScanSums>& s) {
  return {{s[0], s[1], s[2]}, s[3], static_cast<std::size_t>(s[4]), static_cast<std::size_t>(s[5])};
}

}  // namespace mpdem
