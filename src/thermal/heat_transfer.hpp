#pragma once
// HeatTransfer: heat flows into the particles (physics.md section 8), added to Particles::heat
// for the temperatures and positions currently stored:
//   - conduction between touching particles over the Verlet pair list (88)-(90),
//   - conduction to touching barrier elements that carry a fixed temperature (the particle's
//     own k, the area of the sphere cut by the contact plane, the centre-to-plane distance),
//   - convection to the air (91)-(93), the relative speed clamped to the fit's [0, 20] m/s,
//   - radiation to the surroundings (94)-(95).
// Pair heat is written per list slot and gathered per particle in a fixed order (own slots,
// then incoming slots), so Q_ji = -Q_ij holds exactly and totals do not depend on threads.
#include <cstdint>
#include <vector>

#include "model/scene.hpp"
#include "neighbor/neighbor_search.hpp"
#include "state/barrier_topology.hpp"

namespace mpdem {

// Totals of one evaluation, power INTO the particles (W) from each exchange with the outside.
// Conduction between particles is internal and sums to zero.
struct HeatFlows {
  double barriers = 0.0;    // W, from fixed-temperature barriers
  double convection = 0.0;  // W, from the air
  double radiation = 0.0;   // W, from the surroundings
};

class HeatTransfer {
 public:
  // Barrier topology is built only when some element has a fixed temperature.
  HeatTransfer(const Model& model, const Barriers& b);

  // Adds every enabled heat flow to p.heat. The list must be current for p.x; barriers at
  // the evaluated time.
  HeatFlows evaluate(Particles& p, const Barriers& b, const NeighborSearch& search);

  // Evaluations in which some particle's air speed exceeded the fit's 20 m/s (clamped).
  std::uint64_t clamped_evaluations() const { return clamped_; }

 private:
  const Material& material(const Particles& p, std::size_t i) const {
    return model_.materials[static_cast<std::size_t>(p.material[i])];
  }
  const Model& model_;  // conductivity and emissivity by material
  ThermalParams prm_;
  bool barrier_heat_ = false;  // conduction on and some barrier has a fixed temperature
  BarrierTopology topo_;
  std::vector<double> pair_heat_;  // [pairs] W, into the slot's first member (second gets -)
  std::uint64_t clamped_ = 0;
};

// Stored thermal energy sum m c T of the particles [J] (lumped, c of each particle's material),
// thread-count independent.
double thermal_energy(const Model& model, const Particles& p);

// Barrier conduction path length d_b = R - overlap (centre to the cutting plane), kept above
// 1e-3 R so a centre pushed onto the plane does not give an infinite flow.   [m]
double barrier_conduction_distance(double R, double overlap);

}  // namespace mpdem
