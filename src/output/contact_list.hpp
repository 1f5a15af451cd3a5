#pragma once
// The contact list of the last evaluation (the Python module's Simulation.contacts(): force
// chains, contact-level analysis): every particle-particle contact from the pair records
// (Interactions::record_contacts on before that evaluation) and every particle-barrier contact
// from the barrier contact store, which keeps them anyway. With cohesion (contact/cohesive_contact.hpp)
// a listed entry is a contact, a liquid bridge or both, and may be apart (overlap < 0: a gap).
#include <cstdint>
#include <optional>
#include <vector>

#include "contact/barrier_contact_store.hpp"
#include "contact/cohesive_contact.hpp"
#include "contact/contact_record.hpp"
#include "core/vec3.hpp"
#include "interact/interactions.hpp"
#include "state/bodies.hpp"

namespace mpdem {

struct ContactEntry {
  std::int64_t first = -1;      // id of the particle the forces act on
  std::int64_t second = -1;     // id of the other particle, or -1 for a barrier contact
  std::int64_t element = -1;    // id of the barrier element, or -1 for a pair
  Vec3 point;                   // m, contact point (pairs: on the line of centres, mid-overlap or mid-gap)
  Vec3 normal;                  // -, unit, towards `first`
  double overlap = 0.0;         // m, < 0: a gap (a liquid bridge, or a JKR neck held past touching)
  Vec3 normal_force;            // N, on `first` (the other body takes minus it)
  Vec3 tangential_force;        // N, on `first`
  bool sliding = false;         // at the Coulomb limit (pairs; barrier contacts: the committed slip)
  bool touching = false;        // a contact law acts: a contact (JKR: its neck, also past touching), as counted by
                                // contacts_pp / contacts_pb
  bool bridge = false;          // a liquid bridge acts (a bridge alone is not a contact)
  std::size_t first_index = 0;  // index of `first` in the particle arrays (of the listing)
  Vec3 centre;                  // m, first's centre
  Vec3 branch;  // m, centre - the other's centre (its image across a periodic boundary) or - the contact point
  // Clumps: the ids of the bodies `first` and `second` are members of (kNoBody: a free sphere, or
  // no second particle)
  std::int64_t first_body = kNoBody, second_body = kNoBody;
};

// Pairs first (by slot), then barrier contacts (by particle); empty of pairs when recording is off.
std::vector<ContactEntry> contact_list(const Particles& p, const Barriers& b, const Interactions& in);

// The entry of pair record r between particles i (the slot's first member) and j (indices; j may
// be a periodic image); none when nothing acts (r.live == 0).
std::optional<ContactEntry> pair_entry(const Particles& p, std::size_t i, std::size_t j, const PairRecord& r);

// What acts at a barrier contact (kLawFormed | kBridgeFormed, 0: nothing) from its committed state
// (0 in a scene without cohesion, where every detected contact touches: overlap > 0).
inline std::uint32_t barrier_live(std::uint32_t state, double overlap) {
  return state != 0 ? state : (overlap > 0.0 ? kLawFormed : 0u);
}

// The entry of particle i's barrier contact with element id `element` (its committed slot and its
// load); none when nothing acts (a formed contact that broke at this evaluation).
std::optional<ContactEntry> barrier_entry(const Particles& p, std::size_t i, std::int64_t element,
                                          const BarrierSlot& slot, const BarrierLoad& load);

}  // namespace mpdem
