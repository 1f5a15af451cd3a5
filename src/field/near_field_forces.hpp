#pragma once
// NearFieldForces: Coulomb (44) and empirical power-law (46) forces between every pair of
// particles closer than the cutoff (physics.md section 4), over the Verlet pair list (which
// Interactions builds with the cutoff as extra range, see near_field_extra_range).
//
// The empirical coefficients are global or per material pair: the scene's pairs (by material
// names) are resolved once into a small symmetric table indexed by material indices. Pair
// forces are written per list slot and gathered per particle in a fixed order (own slots, then
// incoming slots), so totals do not depend on the thread count and f_ji = -f_ij holds exactly.
#include <cstddef>
#include <vector>

#include "model/scene.hpp"
#include "physics/near_field.hpp"
#include "neighbor/neighbor_search.hpp"

namespace mpdem {

// True when the scene turns either near-field law on.
bool near_field_enabled(const NearFieldParams& nf);
// Extra neighbour-list range [m] that keeps every pair within the cutoff in the list:
// max(0, cutoff - 2 R_min) when the near field is on, else 0.
double near_field_extra_range(const NearFieldParams& nf, const Particles& p);

class NearFieldForces {
 public:
  explicit NearFieldForces(const Model& model);

  bool enabled() const { return coulomb_ || empirical_; }
  double cutoff() const { return cutoff_; }  // m

  // Adds the near-field forces to p.force; returns the potential energy [J] of the pairs
  // within the cutoff. The list must be current for p.x.
  double evaluate(Particles& p, const NeighborSearch& search);

  // Coefficients of (46) between materials a and b (indices into Model::materials).
  const EmpiricalLaw& law(int a, int b) const {
    return table_[static_cast<std::size_t>(a) * materials_ + static_cast<std::size_t>(b)];
  }

 private:
  bool coulomb_ = false;
  bool empirical_ = false;
  double cutoff_ = 0.0;  // m
  double kc_ = 0.0;      // N m^2/C^2, 1/(4 pi eps0 eps_r)
  std::size_t materials_ = 0;
  std::vector<EmpiricalLaw> table_;  // [materials^2] symmetric coefficient table
  std::vector<Vec3> force_;          // [pairs] N, force on the slot's first member
};

}  // namespace mpdem
