#include "field/near_field_forces.hpp"

#include <algorithm>

#include "core/deterministic_sum.hpp"
#include "core/parallel.hpp"

namespace mpdem {

bool near_field_enabled(const NearFieldParams& nf) { return (nf.coulomb || nf.empirical) && nf.cutoff > 0.0; }

double near_field_extra_range(const NearFieldParams& nf, const Particles& p) {
  if (!near_field_enabled(nf) || p.size() == 0) return 0.0;
  const double rmin = *std::min_element(p.radius.begin(), p.radius.end());
  // The list holds pairs with d < R_i + R_j + extra (+ skin); the smallest pair needs the most.
  return std::max(0.0, nf.cutoff - 2.0 * rmin);
}

NearFieldForces::NearFieldForces(const Model& model) {
  const NearFieldParams& nf = model.params.near_field;
  if (!near_field_enabled(nf)) return;
  coulomb_ = nf.coulomb;
  empirical_ = nf.empirical;
  cutoff_ = nf.cutoff;
  kc_ = coulomb_constant(nf.permittivity);
  // Global coefficients everywhere, then the per-pair overrides (both orders: the law is symmetric).
  materials_ = std::max<std::size_t>(1, model.materials.size());
  table_.assign(materials_ * materials_, EmpiricalLaw{nf.a1, nf.b1, nf.a2, nf.b2});
  for (const NearFieldPair& pr : nf.pairs) {
    const int a = model.material_index(pr.material_a), b = model.material_index(pr.material_b);
    if (a < 0 || b < 0) continue;  // the scene reader has rejected unknown names already
    const EmpiricalLaw c{pr.a1, pr.b1, pr.a2, pr.b2};
    table_[static_cast<std::size_t>(a) * materials_ + static_cast<std::size_t>(b)] = c;
    table_[static_cast<std::size_t>(b) * materials_ + static_cast<std::size_t>(a)] = c;
  }
}

double NearFieldForces::evaluate(Particles& p, const NeighborSearch& search) {
  if (!enabled()) return 0.0;
  const VerletList& list = search.pairs();
  const std::size_t n = p.size();
  force_.resize(list.num_pairs());
  const auto& off = list.offsets();
  const auto& idx = list.indices();
  const double rc2 = cutoff_ * cutoff_;

  // 1. Pair laws, one slot at a time (each slot written by one thread); pairs beyond the
  //    cutoff get a zero force, so the gather needs no flags.
  const auto sums = deterministic_sums<1>(n, [&](std::size_t i, std::array<double, 1>& acc) {
    for (std::size_t k = off[i]; k < off[i + 1]; ++k) {
      const std::size_t j = idx[k];
      const Vec3 dx = p.x[i] - p.x[j];
      const double d2 = norm2(dx);
      if (!(d2 < rc2) || d2 == 0.0) {  // outside the range; coincident centres have no direction
        force_[k] = Vec3{};
        continue;
      }
      const double d = std::sqrt(d2);
      double f = 0.0;  // N, along n_ij
      if (coulomb_) {
        f += coulomb_force(kc_, p.charge[i], p.charge[j], d);  // (44)
        acc[0] += coulomb_potential(kc_, p.charge[i], p.charge[j], d);
      }
      if (empirical_) {
        const EmpiricalLaw& c = law(p.material[i], p.material[j]);
        f += empirical_force(c, d);  // (46)
        acc[0] += empirical_potential(c, d);
      }
      force_[k] = (f / d) * dx;
    }
  });

  // 2. Gather per particle in a fixed order: own slots, then incoming slots (third law); ghosts
  //    too (their share is folded onto their sources afterwards).
  const std::size_t all = list.size();
#pragma omp parallel for schedule(static) if (all > kParallelThreshold)
  for (std::size_t i = 0; i < all; ++i) {
    Vec3 f{};
    for (std::size_t k = off[i]; k < off[i + 1]; ++k) f += force_[k];
    for (std::uint32_t k : search.incoming(i)) f -= force_[k];
    p.force[i] += f;
  }
  return sums[0];
}

}  // namespace mpdem
