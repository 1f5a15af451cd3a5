#pragma once
// BarrierContacts: Hertz-Mindlin contacts between particles and barrier triangles (physics.md
// section 7): exact closest-point detection counting each physical contact once, the barrier's
// surface velocity at the contact point (translation, plus omega x (p - pivot) for a rotating
// element) in the relative velocity, the barrier's own E and nu, r* = R, m* = m. The springs of a
// rotating element's contacts turn with it by the step's rotation before their increment.
//
// History: each particle keeps up to kSlots contacts (element, spring, start-of-step tangential
// velocity, normal). A contact that moves onto a neighbouring element of the same surface (a
// sphere rolling across a seam) inherits the spring of the contact that just ended there, so
// tangential forces do not jump at seams. An element switched off (Barriers::active) is in no
// candidate list, so its contacts end: no force, no load, and its history is neither matched nor
// inherited (gone at the next commit). The records live in a BarrierContactStore, only for
// the particles near a barrier; an evaluation visits only those, in parallel. Loads on the
// elements (force, moment about the centre, pressure) are summed per element in particle order,
// independent of the thread count.
//
// Speed (the particles near walls are scattered over the particle arrays; one contact is a long
// chain of roots and divisions): the element triangles are derived once per evaluation, the
// data of the particles a few visits ahead is prefetched, the contact law runs over batches of
// contacts (BarrierBatch, vectorised), and a single thread adds the loads to the elements as it
// goes. None of it changes a result: the arithmetic and every sum's order are those of one
// contact after the other.
#include <array>
#include <bit>
#include <cstdint>
#include <span>
#include <vector>

#include "physics/barrier_contact_detect.hpp"
#include "contact/contact_table.hpp"
#include "contact/barrier_contact_store.hpp"
#include "parallel/attached_records.hpp"
#include "contact/eval_request.hpp"
#include "neighbor/neighbor_search.hpp"
#include "contact/particle_contacts.hpp"
#include "state/barrier_topology.hpp"

namespace mpdem {

struct BarrierBatch;  // contacts evaluated together (contact/barrier_batch.hpp)

// Pa, the pressure on element e from the summed force on it (barrier_contact_loads.cpp).
double element_pressure(const Barriers& b, std::size_t e);

class BarrierContacts {
 public:
  static constexpr int kSlots = BarrierContactStore::kSlots;  // simultaneous barrier contacts per particle

  // The laws come from `table` (its owner, Interactions, rebuilds it from the model at every
  // evaluation), by the particles' and elements' materials.
  BarrierContacts(const ContactTable& table, const Barriers& b);

  // Adds contact forces/torques to the particles and loads to the barriers.
  PairStats evaluate(Particles& p, Barriers& b, const NeighborSearch& search, const EvalRequest& req);
  // evaluate() in three parts, like ParticleContacts': begin() on one thread (false: no barrier
  // or particle, nothing to do), run_groups() on every thread of the team (or the one thread
  // outside a region), with a barrier at its end, finish() on one thread.
  bool begin(Particles& p, Barriers& b, const NeighborSearch& search, const EvalRequest& req);
  void run_groups(Particles& p, Barriers& b, const NeighborSearch& search, const EvalRequest& req);
  PairStats finish(Barriers& b, const EvalRequest& req);
  // Keeps the history with its particles when they are reordered or removed.
  void permute(const std::vector<std::uint32_t>& order) { store_.permute(order); }
  void compact(const std::vector<char>& keep) { store_.compact(keep); }
  std::uint64_t overflows() const { return overflows_; }  // contacts dropped beyond kSlots
  OverlapReport max_overlap(const Particles& p, const Barriers& b) const;
  void save(BinaryWriter& w) const;  // checkpoints: the committed history
  void restore(BinaryReader& r, std::size_t particles);
  // The committed history keyed by particle id (barrier_contact_migration.cpp), for particles
  // that change rank, and back onto the particles' current indices (replacing every record).
  AttachedRecords export_records(const Particles& p) const;
  void import_records(const Particles& p, const AttachedRecords& records);
  // Writes records (of several ranks, gathered) in the form of save() for the particles whose ids,
  // ascending, are `ids`, and the ranks' summed overflows: a checkpoint of a decomposed run.
  static void save_records(BinaryWriter& w, const AttachedRecords& records, std::span<const std::int64_t> ids,
                           std::uint64_t overflows);
  // On several ranks the overflows are counted once, by rank 0 (after a restore of every record).
  void clear_overflows() { overflows_ = 0; }
  std::size_t memory_bytes() const { return store_.bytes(); }  // B, held by the contact records
  // The contact records: after a committed evaluation, committed(k) and loads(k) hold its
  // contacts, load_used(k) of them (output/contact_list.cpp reads them).
  const BarrierContactStore& store() const { return store_; }
  // Cohesion: how far beyond touching contacts are detected (m, >= 0: the largest break or
  // rupture distance of the table's barrier pairs; contact/cohesion_reach.hpp), and whether the
  // contacts keep a cohesion state; set by the owner (0: the plain contacts).
  void set_gap(double gap, bool cohesive) {
    gap_ = gap;
    cohesive_ = cohesive;
  }

 private:
  // {contacts, elastic energy J, normal damping power W, rolling friction power W, dropped
  // contacts, tangential loss J of the sticking and of the sliding contacts, stored springs'
  // energy J at this step's stiffness and of the new springs (ContactResult), bridges held,
  // contacts and bridges broken, the energy they held J, the contacts' |stored energy| J (cohesion)}
  using BarrierSums = std::array<double, 14>;
  // A contact without history takes that of a seam neighbour's whose normal is within ~25 degrees.
  static constexpr double kInheritCos = 0.9;
  // Contacts of active particle k, stage 1: detects them, finds their history, sets its record
  // counts and appends the contacts with the particle's values to the batch (acc[4]: dropped).
  // kRotating: some element rotates (surface velocity at the contact point, springs turned).
  template <bool kRotating>
  void collect(std::size_t k, const Particles& p, const Barriers& b, const BarrierBroadphase& broad,
               const EvalRequest& req, std::vector<BarrierContact>& found, BarrierBatch& batch, BarrierSums& acc);
  // The law over the batch, then in particle and contact order: the tentative history and loads,
  // the particles' force and torque, and the sums acc; with loads_to, also each load onto its element. Empties the
  // batch.
  void flush(Particles& p, Barriers* loads_to, const EvalRequest& req, BarrierBatch& batch, BarrierSums& acc);
  // Sums the loads of the last evaluation onto element e, over its users in particle order.
  void element_loads(Barriers& b, std::size_t e);
  // Cohesion (barrier_contact_cohesion.cpp): particle i's contacts detected gap_ beyond touching,
  // those apart kept only when a formed neck or bridge of its committed records `old` may hold on;
  // the bridge law of a particle and an element by their materials (null: no bridges); and, at a
  // commit, the formed records no contact of the batch took (`taken`, its last `count` history
  // pointers) booked as broken into acc (counts and energy, BarrierSums order).
  void detect_cohesive(std::size_t i, const Particles& p, const Barriers& b, std::span<const std::uint32_t> cand,
                       const BarrierSlot* old, int old_used, std::vector<BarrierContact>& found) const;
  const BridgeLaw* bridge_of(int particle_material, int element_material) const;
  void book_undetected(int particle_material, const Barriers& b, double r, const BarrierSlot* old, int old_used,
                       const BarrierSlot* const* taken, std::size_t count, BarrierSums& acc) const;

  const ContactTable& table_;
  BarrierTopology topo_;
  BarrierContactStore store_;
  std::vector<BarrierSums> partial_;   // [groups] sums of one evaluation, per group
  std::vector<CurrentTriangle> tris_;  // [M] the elements at this evaluation's offsets
  std::vector<Vec3> centres_;          // [M] m, their centroids (Barriers::centre), moment arms
  std::vector<Mat3> step_turn_;        // [L] -, each rotation law's turn since the step's start
  std::uint64_t overflows_ = 0;
  double gap_ = 0.0;       // m, see set_gap
  bool cohesive_ = false;  // see set_gap
  bool direct_ = false;    // this evaluation's loads went onto the elements during the particle loop
};

}  // namespace mpdem
