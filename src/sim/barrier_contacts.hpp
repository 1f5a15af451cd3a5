#pragma once
// BarrierContacts: Hertz-Mindlin contacts between particles and barrier triangles (physics.md
// section 7): exact closest-point detection counting each physical contact once, the barrier's
// motion-law velocity in the relative velocity, the barrier's own E and nu, r* = R, m* = m.
//
// History: each particle keeps up to kSlots contacts (element, spring, start-of-step tangential
// velocity, normal). A contact that moves onto a neighbouring element of the same surface (a
// sphere rolling across a seam) inherits the spring of the contact that just ended there, so
// tangential forces do not jump at seams. Loads on the elements (force, moment about the centre,
// pressure) are accumulated in particle order, independent of the thread count.
#include <cstdint>
#include <vector>

#include "physics/barrier_contact_detect.hpp"
#include "physics/contact_model.hpp"
#include "sim/interactions.hpp"
#include "sim/neighbor_search.hpp"
#include "sim/particle_contacts.hpp"
#include "state/barrier_topology.hpp"

namespace mpdem {

class BarrierContacts {
 public:
  static constexpr int kSlots = 8;  // simultaneous barrier contacts per particle

  BarrierContacts(const ContactModel& law, const Barriers& b);

  // Adds contact forces/torques to the particles and loads to the barriers.
  PairStats evaluate(Particles& p, Barriers& b, const NeighborSearch& search, const EvalRequest& req);
  // Keeps the per-particle history aligned when particles are reordered or removed.
  void permute(const std::vector<std::uint32_t>& order);
  void compact(const std::vector<char>& keep);
  std::uint64_t overflows() const { return overflows_; }  // contacts dropped beyond kSlots
  OverlapReport max_overlap(const Particles& p, const Barriers& b) const;
  void save(BinaryWriter& w) const;  // checkpoints: the committed history
  void restore(BinaryReader& r, std::size_t particles);

 private:
  struct Slot {
    std::int32_t element = -1;  // -1 = empty
    Vec3 spring;                // m
    Vec3 vt0;                   // m/s
    Vec3 normal;                // -, contact normal (towards the particle)
    bool slipped = false;       // the Coulomb limit was hit
    Vec3 wr0;                   // rad/s, the particle's rotation at the step start (rolling law)
  };
  struct Load {                 // one contact's action on its element
    std::int32_t element = -1;
    Vec3 force;                 // N, on the element
    Vec3 point;                 // m, contact point
    double overlap = 0.0;       // m
  };
  struct FirstSlot {            // the first iteration's stick/slip decision of one contact
    std::int32_t element = -1;
    bool slipped = false;
  };
  void resize(std::size_t n);
  void recount();  // used_ from committed_ after restore/permute/compact

  ContactModel law_;
  BarrierTopology topo_;
  std::vector<Slot> committed_;    // [N * kSlots]
  std::vector<Slot> tentative_;    // [N * kSlots]
  std::vector<FirstSlot> first_;   // [N * kSlots] contacts of the step's first iteration
  std::vector<Load> loads_;        // [N * kSlots]
  // Filled slots per particle (slots are packed from 0; the rest are empty), so particles away
  // from the walls cost neither clearing nor reading 8 slots per evaluation.
  std::vector<std::uint8_t> committed_used_;   // [N] of committed_
  std::vector<std::uint8_t> tentative_used_;   // [N] of tentative_ (may overestimate)
  std::vector<std::uint8_t> first_used_;       // [N] of first_
  std::vector<std::uint8_t> load_used_;        // [N] of loads_ (the last evaluation)
  bool counts_valid_ = false;                  // false after restore/permute/compact
  std::uint64_t overflows_ = 0;
};

}  // namespace mpdem
