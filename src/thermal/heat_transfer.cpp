#include "thermal/heat_transfer.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "core/deterministic_sum.hpp"
#include "core/parallel.hpp"
#include "physics/barrier_contact_detect.hpp"
#include "model/body_members.hpp"
#include "physics/heat.hpp"

namespace mpdem {

double thermal_energy(const Model& model, const Particles& p) {
  return deterministic_sums<1>(p.size(), [&](std::size_t i, std::array<double, 1>& acc) {
    acc[0] += represented_mass(model, p, i) * model.materials[static_cast<std::size_t>(p.material[i])].heat_capacity *
              p.T[i];
  })[0];
}

double barrier_conduction_distance(double R, double overlap) { return std::max(R - overlap, 1e-3 * R); }

HeatTransfer::HeatTransfer(const Model& model, const Barriers& b) : model_(model), prm_(model.params.thermal) {
  const bool fixed = std::any_of(b.temperature.begin(), b.temperature.end(), [](double t) { return std::isfinite(t); });
  barrier_heat_ = prm_.conduction && fixed;
  if (barrier_heat_) topo_ = BarrierTopology::build(b);
}

HeatFlows HeatTransfer::evaluate(Particles& p, const Barriers& b, const NeighborSearch& search) {
  const std::size_t n = p.size();
  const VerletList& list = search.pairs();
  const auto& off = list.offsets();
  const auto& idx = list.indices();

  // 1. Conduction between touching particles, one value per list slot (zero when apart).
  if (prm_.conduction) {
    pair_heat_.resize(list.num_pairs());
#pragma omp parallel for schedule(static) if (n > kParallelThreshold)
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t k = off[i]; k < off[i + 1]; ++k) {
        const std::size_t j = idx[k];
        const double d = norm(p.x[i] - p.x[j]);
        if (!(d < p.radius[i] + p.radius[j]) || d == 0.0) {
          pair_heat_[k] = 0.0;
          continue;
        }
        const double A = contact_area_pair(d, p.radius[i], p.radius[j]);  // (89)
        const double K = pair_conductivity(material(p, i).conductivity, material(p, j).conductivity);
        pair_heat_[k] = conduction_heat(K, A, d, p.T[i], p.T[j]);  // (88)
      }
    }
  }

  // 2. Per particle: gather the pair flows in a fixed order, then the exchanges with barriers,
  //    air and surroundings. acc: barrier, convection, radiation (W), clamped speeds (count).
  const bool conduction = prm_.conduction, convection = prm_.convection, radiation = prm_.radiation;
  const BarrierBroadphase& broad = search.barrier_candidates();
  const auto sums = deterministic_sums<4>(n, [&](std::size_t i, std::array<double, 4>& acc) {
    double q = 0.0;  // W
    if (conduction) {
      for (std::size_t k = off[i]; k < off[i + 1]; ++k) q += pair_heat_[k];
      for (std::uint32_t k : search.incoming(i)) q -= pair_heat_[k];
    }
    if (barrier_heat_) {
      thread_local std::vector<BarrierContact> found;
      detect_barrier_contacts(b, topo_, p.x[i], p.radius[i], broad.candidates(i), found);
      for (const BarrierContact& c : found) {
        const double Tb = b.temperature[c.element];
        if (!std::isfinite(Tb)) continue;  // insulated element
        const double R = p.radius[i];
        const double A = contact_area_plane(R, c.overlap);
        const double qb = conduction_heat(material(p, i).conductivity, A, barrier_conduction_distance(R, c.overlap),
                                          p.T[i], Tb);
        q += qb;
        acc[0] += qb;
      }
    }
    if (convection) {
      const double v = norm(p.v[i] - prm_.air_velocity);
      if (v > kConvectionMaxSpeed) acc[3] += 1.0;
      const double qc = convection_heat(convection_coefficient(v), p.radius[i], prm_.air_temperature,
                                        p.T[i]);  // (91)-(93)
      q += qc;
      acc[1] += qc;
    }
    if (radiation) {
      const double qr = radiation_heat(material(p, i).emissivity, p.radius[i], prm_.environment_temperature,
                                       p.T[i]);  // (95)
      q += qr;
      acc[2] += qr;
    }
    p.heat[i] += q;
  });
  // Ghosts are second members only: their conduction comes in through incoming slots (and is
  // folded onto their sources afterwards).
  if (conduction)
    for (std::size_t i = n; i < list.size(); ++i)
      for (std::uint32_t k : search.incoming(i)) p.heat[i] -= pair_heat_[k];

  if (sums[3] > 0.0) {
    if (clamped_ == 0)
      fmt::print(stderr,
                 "\nwarning: a particle moves faster than {} m/s relative to the air; the convection fit (93) is "
                 "only valid below that speed, so h is evaluated at {} m/s (printed once)\n",
                 kConvectionMaxSpeed, kConvectionMaxSpeed);
    ++clamped_;
  }
  return {sums[0], sums[1], sums[2]};
}

}  // namespace mpdem
