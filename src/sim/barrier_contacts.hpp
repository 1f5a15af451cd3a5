#pragma once
// BarrierContacts: Hertz-Mindlin contacts between particles and barrier triangles (physics.md
// section 7): exact closest-point detection counting each physical contact once, the barrier's
// motion-law velocity in the relative velocity, the barrier's own E and nu, r* = R, m* = m.
//
// History: each particle keeps up to kSlots contacts (element, spring, start-of-step tangential
// velocity, normal). A contact that moves onto a neighbouring element of the same surface (a
// sphere rolling across a seam) inherits the spring of the contact that just ended there, so
// tangential forces do not jump at seams. The records live in a BarrierContactStore, only for
// the particles near a barrier; an evaluation visits only those, in parallel. Loads on the
// elements (force, moment about the centre, pressure) are summed per element in particle order,
// independent of the thread count.
#include <array>
#include <cstdint>
#include <vector>

#include "physics/barrier_contact_detect.hpp"
#include "physics/contact_model.hpp"
#include "sim/barrier_contact_store.hpp"
#include "sim/interactions.hpp"
#include "sim/neighbor_search.hpp"
#include "sim/particle_contacts.hpp"
#include "state/barrier_topology.hpp"

namespace mpdem {

class BarrierContacts {
 public:
  static constexpr int kSlots = BarrierContactStore::kSlots;  // simultaneous barrier contacts per particle

  BarrierContacts(const ContactModel& law, const Barriers& b);

  // Adds contact forces/torques to the particles and loads to the barriers.
  PairStats evaluate(Particles& p, Barriers& b, const NeighborSearch& search, const EvalRequest& req);
  // Keeps the history with its particles when they are reordered or removed.
  void permute(const std::vector<std::uint32_t>& order) { store_.permute(order); }
  void compact(const std::vector<char>& keep) { store_.compact(keep); }
  std::uint64_t overflows() const { return overflows_; }  // contacts dropped beyond kSlots
  OverlapReport max_overlap(const Particles& p, const Barriers& b) const;
  void save(BinaryWriter& w) const;  // checkpoints: the committed history
  void restore(BinaryReader& r, std::size_t particles);
  std::size_t memory_bytes() const { return store_.bytes(); }  // B, held by the contact records

 private:
  // Contacts of active particle k: fills its tentative history and loads, adds to its force and
  // torque, and to acc = {contacts, elastic energy J, damping power W, friction power W, dropped}.
  void particle_contacts(std::size_t k, Particles& p, const Barriers& b, const BarrierBroadphase& broad,
                         const EvalRequest& req, std::array<double, 5>& acc);
  void element_loads(Barriers& b);  // sums the loads of the last evaluation onto the elements

  ContactModel law_;
  BarrierTopology topo_;
  BarrierContactStore store_;
  std::vector<std::array<double, 5>> partial_;  // [groups] sums of one evaluation, per group
  std::uint64_t overflows_ = 0;
};

}  // namespace mpdem
