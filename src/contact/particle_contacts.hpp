#pragma once
// ParticleContacts: Hertz-Mindlin contacts between particles (physics.md sections 5-6) over the
// Verlet pair list, with the tangential spring history of every pair.
//
// Each pair slot k of the list holds the committed spring s [m] (the trapezoidal rule also the
// tangential velocity at the start of the step vt0 [m/s]); only a commit evaluation updates them,
// in place. Forces are added block by block in slot order (neighbor/pair_blocks.hpp,
// contact/pair_batch.hpp), so totals do not depend on the thread count and f_ji = -f_ij exactly.
#include <type_traits>
#include <cstdint>
#include <vector>

#include "contact/contact_table.hpp"
#include "contact/eval_request.hpp"
#include "neighbor/neighbor_search.hpp"
#include "contact/pair_batch.hpp"

namespace mpdem {

// Contact history of one pair, keyed by the ids of its members (first = the member the spring
// acts on), used to carry springs across list rebuilds and reorderings.
struct PairHistory {
  std::int64_t id_first = 0, id_second = 0;
  Vec3 spring;              // m
  Vec3 vt0;                 // m/s
  Vec3 wr0;                 // rad/s, relative rotation w_first - w_second at the step start
  std::uint64_t state = 0;  // kLawFormed | kBridgeFormed (contact/pair_batch.hpp), cohesion only
};
// Checkpoints hold these records byte for byte: a layout change is a format change.
static_assert(sizeof(PairHistory) == 96 && std::is_trivially_copyable_v<PairHistory>,
              "PairHistory changed: bump kCheckpointFormat (io/checkpoint_format.hpp) and this size");

struct PairStats {
  std::size_t contacts = 0;
  double elastic_energy = 0.0;  // J
  double damping_power = 0.0;   // W, removed by the normal dashpots
  double rolling_power = 0.0;   // W, removed by rolling friction
  double sticking_loss = 0.0;   // J, tangential loss of the step (ContactResult) of the sticking contacts
  double sliding_loss = 0.0;    // J, tangential loss of the step of the sliding contacts
  double spring_before = 0.0;   // J, the stored springs' energy at this step's stiffness (ContactResult)
  double spring_after = 0.0;    // J, the new springs' energy
  // Cohesion: liquid bridges held, hysteresis contacts and bridges broken at this commit, and the
  // energy they held then (J).
  std::size_t bridges = 0, breaks = 0, ruptures = 0;
  double cohesion_loss = 0.0;
  double elastic_magnitude = 0.0;  // J, sum of the contacts' |stored energy| (cohesion only)
  bool energies = true;            // the energy terms above were computed (compute_energies)
};

// The deepest contact of the last evaluation, relative to the smaller radius.
struct OverlapReport {
  double ratio = 0.0;          // -, overlap / min(R_i, R_j) (particle-barrier: / R_i)
  std::int64_t particle = -1;  // id of the (first) particle
  std::int64_t other = -1;     // id of the other particle, or -1
  std::int64_t element = -1;   // id of the barrier element, or -1
  int rank = -1;               // rank that holds the particle (several ranks; -1 on one)
};

class ParticleContacts {
 public:
  // step_start: keep each contact's tangential velocity (and relative rotation, with rolling
  // resistance) of the step start and the first iteration's stick/slip decisions - what the
  // trapezoidal rule's increment (64) needs. Velocity Verlet (phi = 1, one evaluation a step)
  // needs only the spring.
  // The laws come from `table` (its owner, Interactions, rebuilds it from the model at every
  // evaluation), by the particles' materials.
  ParticleContacts(const ContactTable& table, bool step_start) : table_(table), step_start_(step_start) {}

  // Adds contact forces and torques to p.force / p.torque; list must be current for p.x.
  PairStats evaluate(Particles& p, const NeighborSearch& search, const EvalRequest& req);
  // evaluate() in three parts, for a step that runs its passes in one parallel region
  // (Interactions::evaluate_in_team): begin() on one thread; run_blocks() on every thread of the
  // team (outside a region: on the one thread, which then does all blocks), with a barrier at
  // its end; finish() on one thread, the totals.
  void begin(Particles& p, const NeighborSearch& search, const EvalRequest& req);
  void run_blocks(Particles& p, const NeighborSearch& search);
  PairStats finish();

  // The contact history across a neighbour rebuild, keyed by the particles' indices before it:
  // taken out before the particles are permuted or removed and the list is rebuilt ...
  struct CarriedHistory {
    std::vector<std::uint32_t> offset{0};  // [N_old + 1] CSR over the old first member
    std::vector<std::uint32_t> second;     // [kept] old index of the second member, ascending
    std::vector<Vec3> spring, vt0, wr0;    // [kept] m, m/s, rad/s (vt0, wr0 empty when unused)
    std::vector<std::uint8_t> state;       // [kept] cohesion state (empty without cohesion)
  };
  CarriedHistory carry_history(const NeighborSearch& search);
  // ... and put back onto the rebuilt list; old_index[i] is the old index of particle i.
  void restore_history(const NeighborSearch& search, CarriedHistory h, const std::vector<std::uint32_t>& old_index);

  // The list lost slots without a rebuild (NeighborSearch::compact): slot k's history is that of
  // the old list's slot from[k] (of old_pairs).
  void compact_slots(const std::vector<std::uint32_t>& from, std::size_t old_pairs);

  // History of the touching pairs (ids, springs), for checkpoints ...
  std::vector<PairHistory> export_history(const Particles& p, const NeighborSearch& search) const;
  // ... and back onto the slots of the rebuilt list (spring sign follows the pair's orientation).
  void import_history(const Particles& p, const NeighborSearch& search, std::vector<PairHistory> h);

  // Recording of each contact's force (PairRecord per slot) at every evaluation from now on
  // (off: none kept); records() are the last evaluation's, for the list it was made on.
  void record_contacts(bool on);
  bool recording() const { return recording_; }
  // Off: the evaluations that follow neither compute nor sum the contacts' energy terms (PairPass::
  // energies; [checks] energy_ledger = false, between the steps that write a log row). On, the
  // commits compute them (an iteration of the trapezoidal rule never does); the cohesive kernel
  // always.
  void compute_energies(bool on) { energies_ = on; }
  const std::vector<PairRecord>& records() const { return records_; }

  // The deepest contact of the last evaluation.
  OverlapReport max_overlap() const { return deepest_; }

  // Checkpoints (the list must be restored first).
  void save(BinaryWriter& w, const Particles& p, const NeighborSearch& search) const;
  void restore(BinaryReader& r, const Particles& p, const NeighborSearch& search);

  // For tests: the committed spring of the pair (i, j), or zero when none.
  Vec3 spring_between(const NeighborSearch& search, std::size_t i, std::size_t j) const;
  std::size_t memory_bytes() const;
  // Cohesion: the candidates' reach beyond touching (m, >= 0: the largest break or rupture
  // distance of the table for the scene's particles), set by the owner before evaluations.
  void set_gap(double gap) { gap_ = gap; }
  double gap() const { return gap_; }
  // True when the table has a law with hysteresis or a liquid bridge between particles: the
  // kernel keeps a state per slot.
  bool cohesive() const;
  // For tests: choose the scalar candidate selection even when the AVX-512 one is built in.
  void use_vector_select(bool on) { vector_select_ = on; }

  using Terms = ContactTerms;  // per-particle values of the kernel, contact/pair_batch.hpp

 private:
  void ensure_history(std::size_t pairs);   // sized for the list; table_ must be current (rolling)
  bool holds_history(std::size_t k) const;  // slot k has a spring, vt0 or wr0 to keep
  void refresh_terms(const Particles& p, std::uint64_t generation);

  const ContactTable& table_;
  bool step_start_;
  // Per pair slot [pairs]; the committed history is updated in place by commit evaluations.
  std::vector<Vec3> spring_;           // m, committed tangential spring of the slot's first member
  std::vector<Vec3> vt0_;              // m/s, tangential velocity at the step start (step_start)
  std::vector<Vec3> wr0_;              // rad/s, w_first - w_second at the step start (step_start, mu_r > 0)
  std::vector<std::uint8_t> slipped_;  // stick (0) / slip (1) of the first iteration (step_start)
  std::vector<std::uint8_t> state_;    // kLawFormed | kBridgeFormed, committed (cohesion only, else empty)
  double gap_ = 0.0;                   // m, see set_gap
  // Per cross pair [PairBlocks::num_cross()], the second member's share, added after the block pass:
  std::vector<Vec3> cross_force_;          // N
  std::vector<Vec3> cross_torque_;         // N m
  std::vector<Terms> terms_;               // [N], from the particles' radii and masses
  std::uint64_t terms_generation_ = 0;     // NeighborSearch::generation() they were computed at
  int single_material_ = -1;               // the material of every particle, or -1 (several)
  std::vector<PairBlockSums> block_sums_;  // [blocks]
  std::vector<double> block_seconds_;      // [blocks] s, each block's time at the last evaluation
  std::vector<double> block_cost_;         // [blocks + 1] s, their sum before each block (thread shares)
  OverlapReport deepest_;
  PairPass pass_{};  // the evaluation begin() set up, which run_blocks() runs
  bool vector_select_ = true;
  bool recording_ = false;
  bool energies_ = true;             // see compute_energies
  std::vector<PairRecord> records_;  // [pairs] while recording: the last evaluation's contacts
};

}  // namespace mpdem
