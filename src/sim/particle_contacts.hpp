#pragma once
// ParticleContacts: Hertz-Mindlin contacts between particles (physics.md sections 5-6) over the
// Verlet pair list, with the tangential spring history of every pair.
//
// Each pair slot k of the list holds the committed spring s [m] and the tangential velocity at
// the start of the step vt0 [m/s]; an evaluation computes tentative springs, and a commit
// evaluation stores them. Pair forces are written per slot and gathered per particle in a fixed
// order (own slots, then incoming slots), so totals do not depend on the thread count and
// f_ji = -f_ij holds exactly.
#include <cstdint>
#include <vector>

#include "physics/contact_model.hpp"
#include "sim/interactions.hpp"
#include "sim/neighbor_search.hpp"

namespace mpdem {

// Contact history of one pair, keyed by the ids of its members (first = the member the spring
// acts on), used to carry springs across list rebuilds and reorderings.
struct PairHistory {
  std::int64_t id_first = 0, id_second = 0;
  Vec3 spring;   // m
  Vec3 vt0;      // m/s
  Vec3 wr0;      // rad/s, relative rotation w_first - w_second at the step start
};

struct PairStats {
  std::size_t contacts = 0;
  double elastic_energy = 0.0;      // J
  double damping_power = 0.0;       // W, removed by normal + tangential damping
  double friction_power = 0.0;      // W, removed by sliding and rolling friction
};

// The deepest contact of the last evaluation, relative to the smaller radius.
struct OverlapReport {
  double ratio = 0.0;              // -, overlap / min(R_i, R_j) (particle-barrier: / R_i)
  std::int64_t particle = -1;      // id of the (first) particle
  std::int64_t other = -1;         // id of the other particle, or -1
  std::int64_t element = -1;       // id of the barrier element, or -1
};

class ParticleContacts {
 public:
  explicit ParticleContacts(const ContactModel& law) : law_(law) {}

  // Adds contact forces and torques to p.force / p.torque; list must be current for p.x.
  PairStats evaluate(Particles& p, const NeighborSearch& search, const EvalRequest& req);

  // History of the touching pairs (ids, springs), before a rebuild or reordering ...
  std::vector<PairHistory> export_history(const Particles& p, const NeighborSearch& search) const;
  // ... and back onto the slots of the rebuilt list (spring sign follows the pair's orientation).
  void import_history(const Particles& p, const NeighborSearch& search, std::vector<PairHistory> h);

  OverlapReport max_overlap(const Particles& p, const NeighborSearch& search) const;

  // Checkpoints (the list must be restored first).
  void save(BinaryWriter& w, const Particles& p, const NeighborSearch& search) const;
  void restore(BinaryReader& r, const Particles& p, const NeighborSearch& search);

  // For tests: the committed spring of the pair (i, j), or zero when none.
  Vec3 spring_between(const NeighborSearch& search, std::size_t i, std::size_t j) const;

 private:
  ContactModel law_;
  // Per pair slot [pairs]:
  std::vector<Vec3> spring_;        // m, committed tangential spring of the slot's first member
  std::vector<Vec3> vt0_;           // m/s, tangential relative velocity at the step start
  std::vector<Vec3> wr0_;           // rad/s, relative rotation at the step start (rolling law)
  std::vector<Vec3> spring_tent_;   // m, tentative spring of the current evaluation
  std::vector<Vec3> vt_tent_;       // m/s, tangential velocity of the current evaluation
  std::vector<Vec3> wr_tent_;       // rad/s, relative rotation of a commit evaluation
  std::vector<Vec3> force_;         // N, force on the first member (the second gets -force)
  std::vector<Vec3> torque_first_;  // N m
  std::vector<Vec3> torque_second_; // N m
  std::vector<double> overlap_;      // m, overlap of touching slots
  std::vector<std::uint8_t> touching_;
  std::vector<std::uint8_t> slipped_;   // stick (0) / slip (1) decided by the first iteration
  // Per particle [N], refreshed every evaluation (particles may be reordered in between):
  std::vector<double> compliance_;        // 1/Pa, (1 - nu^2)/E
  std::vector<double> shear_compliance_;  // 1/Pa, (2 - nu)/G
  std::vector<double> inv_radius_;        // 1/m
  std::vector<double> inv_mass_;          // 1/kg
};

}  // namespace mpdem
