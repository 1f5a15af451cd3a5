#pragma once
// The contact list of the last evaluation (the Python module's Simulation.contacts(): force
// chains, contact-level analysis): every particle-particle contact from the pair records
// (Interactions::record_contacts on before that evaluation) and every particle-barrier contact
// from the barrier contact store, which keeps them anyway.
#include <cstdint>
#include <vector>

#include "core/vec3.hpp"
#include "interact/interactions.hpp"
#include "state/bodies.hpp"

namespace mpdem {

struct ContactEntry {
  std::int64_t first = -1;      // id of the particle the forces act on
  std::int64_t second = -1;     // id of the other particle, or -1 for a barrier contact
  std::int64_t element = -1;    // id of the barrier element, or -1 for a pair
  Vec3 point;                   // m, contact point (pairs: on the line of centres, mid-overlap)
  Vec3 normal;                  // -, unit, towards `first`
  double overlap = 0.0;         // m
  Vec3 normal_force;            // N, on `first` (the other body takes minus it)
  Vec3 tangential_force;        // N, on `first`
  bool sliding = false;         // at the Coulomb limit (pairs; barrier contacts: the committed slip)
  std::size_t first_index = 0;  // index of `first` in the particle arrays (of the listing)
  Vec3 centre;                  // m, first's centre
  Vec3 branch;  // m, centre - the other's centre (its image across a periodic boundary) or - the contact point
  // Clumps: the ids of the bodies `first` and `second` are members of (kNoBody: a free sphere, or
  // no second particle)
  std::int64_t first_body = kNoBody, second_body = kNoBody;
};

// Pairs first (by slot), then barrier contacts (by particle); empty of pairs when recording is off.
std::vector<ContactEntry> contact_list(const Particles& p, const Barriers& b, const Interactions& in);

}  // namespace mpdem
