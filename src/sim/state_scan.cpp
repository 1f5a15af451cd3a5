#include "sim/state_scan.hpp"

#include "core/deterministic_sum.hpp"

namespace mpdem {

StateScan scan_state(const Particles& p, const FieldParams& fields, const DomainParams& domain) {
  return scan_from_sums(deterministic_sums<kScanSums>(p.size(), [&](std::size_t i, std::array<double, kScanSums>& acc) {
    scan_particle(p, i, fields, domain, acc);
  }));
}

}  // namespace mpdem
